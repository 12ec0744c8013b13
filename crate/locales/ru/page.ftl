# Слова самой страницы (панели, кнопки, подсказки, строка состояния). Каждому сообщению
# соответствует английское в ../en/page.ftl; тест падает, если какого-то нет.

app-title = Attitude Lab — лаборатория ориентации
language = Язык
lab = Работа

## Управление прогоном
play = ▶ Пуск
pause = Пауза
step = Шаг
reset = ⟲ Сброс
reset-hint = Начать заново с t = 0 с зерном, указанным ниже
presenter = Для проектора
presenter-hint = Для проектора: крупный шрифт, толстые линии, только готовые наборы (в ссылке: `presenter=1`)
light = Светлая
light-hint = Светлые панели и тёмный текст для проектора (по умолчанию в режиме проектора; в ссылке: `theme=light` или `theme=dark`)
seed = Зерно
new-seed = Новое зерно
new-seed-hint = Случайное зерно, затем сброс
speed = скорость ×

## Параметры
presets = Готовые наборы:
preset-hint = { $help } — параметры с пометкой «при сбросе» вступают в силу после сброса
all-parameters = Все параметры
parameters = Параметры
defaults = по умолчанию
applies-at-reset = { $help } (вступает в силу при сбросе)
waiting-for-reset = Ждут сброса: { $names }.
reset-now = Сбросить сейчас
reset-now-hint = Начать с t = 0 с этими значениями

## Вывод
ghost = Призрак в 3D
export-csv = Экспорт CSV
export-csv-hint = Все ряды на каждом шаге с t = 0 (прогон повторяется точно; пустые ячейки — пропущенные отсчёты)
copy-link = Копировать ссылку
copy-link-hint = Ссылка, которая восстанавливает работу, зерно, скорость и параметры
copy-python = Копировать как Python
copy-python-hint = Фрагмент pandas + matplotlib, который загружает экспортированный CSV и строит показанный график
png-plots = PNG графиков
png-plots-hint = Все вкладки графиков в этот момент, одна под другой, в одном PNG (клавиша p). У каждого вида своя кнопка PNG, когда над ним указатель.
export-output = Экспорт выходного файла статьи
export-output-hint = Строки самой статьи (t, угол₁, угол₂, угол₃), заново с t = 0 с текущими параметрами, до первой строки в пределах допуска
png = PNG
png-view-hint = Сохранить этот вид как PNG (клавиша p, когда он показан один)

## Справка
what-am-i-looking-at = Что я вижу?
keys-help = Клавиши: пробел — пауза/пуск · r — сброс · s — один шаг · ←/→ — вкладка графика · в уроке PageDown/PageUp или →/← — следующий/предыдущий шаг, Shift+←/→ — вкладка графика · f — один вид во весь размер (ещё раз — следующий вид, затем только графики, затем всё) · p — PNG вида, показанного одного, иначе всех вкладок · ? или F1 — все клавиши (Tab переходит между элементами)
frames-help = Системы координат: опорная ζ вверх; связанная ξ′ вправо, η′ вперёд, ζ′ вверх. Сфера показывает вертикаль k = (a′, b′, c′) в связанных осях; луч из полюса S через k пересекает плоскость тела в точке w = u + jv = (a′ + jb′)/(1 + c′). |w| = 1 — тангаж ±90°; w → ∞ — тело вверх дном, где интегратор (u, v, z) переходит к s = 1/w.

## Узкий экран
controls = Управление
controls-hint = Параметры, готовые наборы и экспорт — на листе снизу
view = Вид:
close = Закрыть

## Графики
estimators = Оценки:
estimators-menu = Оценки
more-estimators = ещё { $n }…
chip-hide-hint = { $name } — нажмите, чтобы скрыть везде
chip-show-hint = { $name } — нажмите, чтобы показать везде
more = Ещё…
more-with = Ещё: { $title }
log10 = log10
bands = полосы ±3σ
outages = отмечать отказы
replay-gaps = нет отсчёта в записи (разрыв или перезапуск часов записи)
outages-hint = Закрасить интервалы, когда датчик ничего не даёт (на всех графиках)
axis-time = t [с]
axis-mixed-units = разные единицы (см. легенду)
axis-value = значение
axis-of-deg = угол
axis-of-deg-s = угловая скорость
axis-of-rad = угол
axis-of-rad-s = угловая скорость
axis-of-nT = поле
axis-of-s = время
axis-of-rad-s2 = угловое ускорение
axis-of-deg-s2 = угловое ускорение
axis-of-N-m-s = кинетический момент
axis-of-1-s2 = возмущение
axis-of-N = сила
axis-of-J = энергия
axis-attitude = угол
axis-rate = угловая скорость
axis-error = ошибка
axis-covariance = ковариация
axis-innovation = невязка
bands-legend = ±3σ по собственной ковариации фильтра
legend-no-data = значений не записано
legend-no-positive = нет значений больше 0 для логарифмической шкалы

## Виды
view-body3d = Тело в 3D
view-sphere = Сфера Римана
view-wplane = Плоскость w
view-dial = Шкала
view-phase = Фазовый портрет
truth = истина
body-truth = истина (сплошное)
body-ghost = оценка (призрак): { $label }
body-no-truth = истины нет: в записи только показания
body-estimate = оценка (сплошное): { $label }
body-hint = перетаскивание: вращение · колесо или щипок: масштаб · двойной щелчок: сброс · x красная, y зелёная, z синяя
body-hint-touch = перетаскивание: вращение · щипок: масштаб · x красная, y зелёная, z синяя
sphere-title = Сфера Римана: вертикаль k в связанных осях
chart-all-w = все фильтры в карте w (из S)
chart-w-rest = { $n ->
    [one] ещё { $n } в карте w (из S)
    [few] ещё { $n } в карте w (из S)
   *[many] ещё { $n } в карте w (из S)
}
chart-s = карта s = 1/w (вверх дном): { $ids }
dial-title = Угол (0° вверху)

## Строка состояния
job-reselect = Повторный прогон моделирования для этого графика
job-export-csv = Выгрузка всех отсчётов в CSV
job-progress = { $what } · { $percent } %
job-holds = моделирование пока стоит
stop = Стоп
status-short = t = { $t } с · ×{ $realtime } реального времени (задано ×{ $asked })
status-long = t = { $t } с · шаг { $step } мс · { $rate } шагов/с · { $realtime } реального времени (задано ×{ $asked }) · кадр { $frame } мс · счёт { $sim } мс/кадр · запись { $mib } МиБ ({ $series } { $series ->
    [one] ряд
    [few] ряда
   *[many] рядов
}, весь прогон)
behind = · не успевает за реальным временем: уменьшите скорость
diverged = · { $id } разошёлся: { $why } (нажмите «Сброс»)
unobservable = · { $id } ненаблюдаем: { $why }
diverged-many = · { $n ->
    [one] { $n } фильтр разошёлся
    [few] { $n } фильтра разошлись
   *[many] { $n } фильтров разошлись
}: какие и почему… (нажмите «Сброс»)
unobservable-many = · { $n ->
    [one] { $n } фильтр ненаблюдаем
    [few] { $n } фильтра ненаблюдаемы
   *[many] { $n } фильтров ненаблюдаемы
}: какие и почему…

## Почему фильтр в беде (после «разошёлся:» или «ненаблюдаем:»)
trouble-not-finite = состояние или ковариация не конечны (NaN или ∞)
trouble-sensitivity-not-finite = Λ, U или p не конечны
trouble-innovation-not-positive = обновление отклонено: H P Hᵀ + R не положительно определена (вырожденная геометрия?)
trouble-measurement-not-finite = обновление отклонено: измерение или результат не конечны
trouble-lost-definiteness = ковариация потеряла положительную определённость: R слишком мала рядом с P для двойной точности
trouble-attitude-lost = 2σ ориентации { $sigma }° (больше { $limit }°): фильтр потерял ориентацию
trouble-angle-ran-away = угол ушёл на { $deg }° от проинтегрированного угла гироскопа (адаптация здесь неустойчива)
trouble-singular-sensitivity = UᵀQU вырождена: увеличьте ε (метод 10)
trouble-sun-along-field = Солнце и поле параллельны с точностью до { $deg }°: вращение вокруг них не наблюдается

## Вкладки групп рядов
group-time = Время
group-attitude = Ориентация
group-rate = Угловые скорости
group-error = Ошибки
group-covariance = Ковариации
group-innovation = Невязки
group-sphere = (u, v) и вертикаль
group-lab = Работа

## Окно клавиш (клавиша ? или F1)
keys-button = Клавиши (?)
keys-button-hint = Все клавиши страницы: переход между элементами, ползунки, ход моделирования (также ? или F1)
keys-title = Клавиатура
keys-intro = До любого элемента управления можно дойти клавишей Tab. Жёлтая или синяя рамка показывает, у какого из них клавиатура.
keys-tab = Tab, Shift+Tab
keys-tab-does = следующий, предыдущий элемент
keys-activate = Enter, пробел
keys-activate-does = нажать кнопку, поставить флажок, открыть список
keys-slider-arrows = ← → (↓ ↑) на ползунке
keys-slider-arrows-does = двадцатая часть его диапазона; с Shift — сотая
keys-slider-pages = PageUp, PageDown
keys-slider-pages-does = десятая часть диапазона ползунка
keys-slider-ends = Home, End
keys-slider-ends-does = наименьшее, наибольшее значение ползунка
keys-escape = Esc
keys-escape-does = уйти с элемента (клавиши ниже снова действуют); закрыть это окно
keys-space = Пробел
keys-space-does = пауза, пуск (когда клавиатура не у элемента)
keys-reset = r
keys-reset-does = сброс: t = 0 с тем же зерном
keys-step = s
keys-step-does = один шаг, на паузе
keys-tabs = ← → (в уроке Shift+← →)
keys-tabs-does = предыдущая, следующая вкладка графика (когда клавиатура не у элемента)
keys-lesson = PageDown или →, PageUp или ← в уроке
keys-lesson-does = следующий, предыдущий шаг урока (эти клавиши посылает пульт докладчика)
keys-full = f
keys-full-does = один вид во весь размер (ещё раз — следующий вид, только графики, всё)
keys-png = p
keys-png-does = PNG вида, показанного одного, иначе всех вкладок графиков

## Живое описание для программы экранного доступа (раз в 10 с во время счёта, сразу при паузе)
live-run = { $lab } — t = { $t } с, { $state }.
live-running = идёт со скоростью ×{ $speed }
live-paused = пауза
live-within = { $name }: ошибка ориентации { $error }°, внутри своей полосы 3σ = { $band }°.
live-outside = { $name }: ошибка ориентации { $error }°, вне своей полосы 3σ = { $band }°.
live-error = { $name }: ошибка ориентации { $error }°.
live-no-truth = { $name }: истинной ориентации для сравнения нет (воспроизводится запись).

## Таблица точности (статья 2)
accuracy-help = σ: наибольшая по осям СКО ошибки относительно истины за последние { $covered } с из { $window } с (вместе со средним); √P: собственное √max diag P фильтра сейчас (мера статьи). Щелчок по строке делает фильтр призраком.
accuracy-filter = фильтр
accuracy-att = σ ориент. °
accuracy-att-p = √P ориент. °
accuracy-paper-att = статья °
accuracy-rate = σ скор. °/с
accuracy-rate-p = √P скор. °/с
accuracy-paper-rate = статья °/с
accuracy-tab-all = все фильтры
accuracy-tab-table = Таблица { $n }

## Лабораторный режим
replay-example = Воспроизвести пример записи
replaying = воспроизводится { $name } ({ $n } отсчётов)
back-to-simulation = Назад к моделированию

## Переборы
sweep-title = Перебор: { $title }
cancel = Отмена
sweep-run = Запустить перебор
sweep-run-hint = По одному прогону на значение и зерно с текущими параметрами; страница продолжает работать
sweep-run-log = Перебор по записи
sweep-run-log-hint = По одному прогону на значение по воспроизводимой записи (истины нет: собственные оценки записи)
sweep-size = { $cells } знач. × { $seeds ->
    [one] { $seeds } зерно
    [few] { $seeds } зерна
   *[many] { $seeds } зёрен
}
sweep-size-grid = { $cells } клеток × { $seeds ->
    [one] { $seeds } зерно
    [few] { $seeds } зерна
   *[many] { $seeds } зёрен
}
sweep-each = по { $s } с
sweep-workers = { $n ->
    [one] в { $n } фоновом потоке
   *[other] в { $n } фоновых потоках
}
sweep-on-log = по воспроизводимой записи
sweep-diverged = { $at }: фильтр разошёлся (пропущенные отсчёты)
sweep-unscored = { $at }: не оценено: { $why }
sweep-skipped = пропущено: { $why }
sweep-best = лучшее для «{ $series }»: { $param } = { $value } (СКЗ { $rms })
sweep-max-axis = log10 max |значение|
sweep-objective-axis = критерий
sweep-argmin = минимум { $name } по { $n } значениям этого перебора: { $at }
sweep-argmin-marker = минимум { $name }
sweep-cell-range = { $value }: медиана { $n } прогонов, разброс от { $lo } до { $hi }
sweep-heat-needs = Для тепловой карты нужно хотя бы по два положительных значения по каждой оси.
sweep-heat-colour = цвет: log10 { $name }, от { $lo } (тёмный) до { $hi } (яркий). Оптимум: { $at } ({ $name } = { $best }).
sweep-heat-filling = цвет: log10 { $name }; клетки заполняются по ходу перебора.
sweep-optimum = оптимум

## Сообщения о том, что сделала страница
msg-no-example-log = у этой работы нет примера записи
msg-python-copied = скопировано: фрагмент на Python, который загружает выгруженный CSV и рисует этот график
msg-no-logs = эта работа не воспроизводит записи
msg-no-logs-named = { $name }: эта работа не воспроизводит записи
msg-log-skipped = { $name }: пропущено — { $why }
msg-log-more-bad = { $name }: … и ещё плохих строк: { $n }
msg-log-replaying = { $name }: воспроизводится { $n } отсчётов из { $lines } строк (переставлено по времени: { $reordered }, слито: { $merged }, отброшено: { $rejected }; разрывов времени: { $gaps })
msg-log-failed = { $name }: { $why }
msg-picker-refused = браузер не открыл окно выбора файла: он открывает его только сразу после щелчка или нажатия клавиши. Нажмите кнопку загрузки ещё раз.
msg-file-unreadable = не удалось прочитать { $name }: { $why }
msg-workers-failed = фоновые потоки перебора остановились ({ $why }); перебор продолжается частями в потоке страницы

## Строка записи, которую не удалось использовать (в «пропущено — …»), и почему
log-line = строка { $line }: { $reason }: «{ $text }»
log-fault-columns = ожидалось столбцов: { $expected } ({ $names }), найдено: { $found }
log-fault-columns-merged = ожидалось столбцов: { $expected } ({ $names }), найдено: { $found } (слились две строки?)
log-fault-before-data = до начала данных (приветствие скетча?)
log-fault-not-a-number = не число: «{ $text }»
log-fault-not-utf8 = не текст UTF-8: байт { $byte } в позиции { $column }
log-fault-not-a-word = «{ $raw }» — не { $bits }-битное слово (0 … { $max })
log-fault-time-glitch = сбой часов: { $t } с между { $last } с и следующими строками
log-fault-duplicate = то же время, что в строке { $line }: её повтор
log-fault-averaged = то же время, что в строке { $line }: усреднено с ней
log-fault-out-of-order = не по порядку: поставлено перед строкой { $line }

## Почему запись целиком нельзя воспроизвести
log-refused-not-replayed = работа { $lab } не воспроизводит записи; их воспроизводят: { $labs }
log-refused-width = строк с { $width } числами: { $lines }, с { $columns }: { $own }; работа { $lab } читает { $format }, чисел в строке: { $columns }.
log-refused-width-like = строк с { $width } числами: { $lines }, с { $columns }: { $own }; работа { $lab } читает { $format }, чисел в строке: { $columns }. Похоже, это { $other } ({ $count ->
        [one] её читает работа
       *[other] её читают работы
    } { $labs }).
log-refused-few = в записи нужно хотя бы два отсчёта с растущим временем (сохранено отсчётов: { $kept } из { $lines } строк, переставлено: { $reordered }, слито: { $merged }, отброшено: { $rejected })
log-refused-few-first = в записи нужно хотя бы два отсчёта с растущим временем (сохранено отсчётов: { $kept } из { $lines } строк, переставлено: { $reordered }, слито: { $merged }, отброшено: { $rejected }; первая плохая строка: { $first })
log-refused-accel = акселерометр показывает медиану { $g } g, а ожидается около 1 g: единица не подходит (единица `{ $unit }` даёт { $gives } g)

## Живые датчики (гироскоп и акселерометр телефона, Arduino через Web Serial)
live-title = Живые датчики
live-help = Фильтры работают на гироскопе и акселерометре этого телефона или на MPU-6050 платы Arduino по USB — по мере поступления отсчётов. Телефон: держите его горизонтально, экраном вверх, верхним краем вперёд; поворачивайте вокруг длинной оси — это ось x модели и крен φ. Arduino: скетч печатает строки `time, ax, ay, az, gx, gy, gz` в единицах, выбранных выше. Нужен https:// или localhost.
live-phone = Датчики этого телефона
live-serial = Arduino по USB (Web Serial)
live-baud = бод
live-phone-source = телефон
live-serial-source = последовательный порт, { $baud } бод
live-rate = { $rate } отсчётов/с
live-ended = поток закончился
live-status = { $source } · { $api } · { $state } · записано строк: { $n }, отброшено: { $rejected }
live-zero = Ноль: текущее положение — горизонт
live-stop = Остановить
live-save = Сохранить запись (CSV)
live-no-detail = без подробностей
live-why-permission-denied = доступ к датчикам движения не разрешён
live-why-sensor-error = сбой датчиков движения: { $detail }
live-why-no-motion = в этом браузере нет датчиков движения
live-why-no-serial = в этом браузере нет Web Serial (Chrome, Edge и Opera на компьютере; Firefox с версии 151)
live-why-no-port = порт не выбран ({ $detail })
live-why-cannot-open = не удаётся открыть порт: { $detail }
live-why-unplugged = устройство отключено
live-why-closed = устройство закрыло поток
live-why-stopped = источник остановлен
live-why-script = сбой сценария датчиков на странице: { $detail }
live-why-desktop-phone = живые датчики работают на веб-странице (в браузере телефона)
live-why-desktop-serial = Web Serial работает на веб-странице (Chrome или Edge на компьютере)
live-why-tap-again = коснитесь страницы ещё раз, чтобы разрешить доступ к датчикам движения
live-why-read-error = ошибка чтения порта, чтение продолжается: { $detail }
msg-live-failed = живые датчики: { $why }
msg-live-waiting = живые датчики: ждём первых отсчётов…
msg-live-zeroed = живые датчики: текущее положение принято за горизонт (следующие отсчёты повёрнуты на него)
msg-live-stalled = живые датчики: нет отсчётов { $s } с (расчёт ждёт, ничего не потеряно)
msg-live-dropped = живые датчики: { $n } отсчётов отброшено, пока страница не рисовалась
msg-live-ended = живые датчики: поток закончился ({ $why }); в записи сохранено хороших строк: { $n }
msg-live-none = нет живого сеанса для сохранения
msg-live-record-saved = хороших строк: { $n }; attlab replay воспроизводит её с теми же оценками
msg-export-failed = выгрузка не удалась: { $why }
msg-export-busy = уже идёт выгрузка: по одной за раз
msg-no-output-file = у этой работы нет выходного файла статьи
msg-output-rows = строк: { $n }
msg-output-rows-stopped = строк: { $n }, до первой строки в пределах допуска
msg-csv-rows = строк: { $n }, каждый отсчёт, пересчитано от t = 0
msg-plot-failed = не удаётся показать этот график: { $why }
msg-plots-lost = графики потеряли историю: { $why }
msg-rerun-took = для этого графика пересчитано { $t } с моделирования за { $ms } мс
msg-preset-applied = набор «{ $name }» применён
msg-preset-waits = набор «{ $name }»: часть значений вступит в силу при сбросе
msg-locked-kept = закреплено ссылкой преподавателя и оставлено как было: { $names }
locked-hint = Закреплено ссылкой преподавателя: наборы, «по умолчанию» и шаги урока его не меняют.
a11y-dot = с точкой
a11y-double-dot = с двумя точками
a11y-resize-panel = Изменить ширину панели
msg-png-lab-changed = выгрузка PNG остановлена: сменилась работа
msg-png-busy = PNG уже делается: по одному за раз
msg-png-failed = выгрузка PNG не удалась: { $why }
png-why-no-picture = отрисовщик не дал снимка за { $n ->
    [one] { $n } кадр
    [few] { $n } кадра
   *[many] { $n } кадров
} (этот отрисовщик не умеет делать снимки)
png-why-off-screen = снимаемой части нет на экране
png-why-empty = нечего сохранять: снимок { $w }×{ $h } пикселей
png-why-too-large = снимок слишком велик: { $w }×{ $h } пикселей
png-why-encoder = кодировщик PNG: { $detail }
saved-downloaded = { $name } скачан
saved-written = сохранено: { $path }
saved-cancelled = сохранение отменено
save-refused = браузер не дал скачать файл: { $detail }
save-cannot-write = не удаётся записать { $path }: { $error }
msg-png-saved = { $saved } ({ $w }×{ $h } пикселей)

## Плохие элементы ссылки, вверху страницы
link-problems = В ссылке есть элементы, которые страница не смогла применить; остальное применено:
link-dismiss = Скрыть
link-bad = Элемент ссылки { $item }: { $why } — пропущен.
link-unknown = Элемент ссылки { $item }: у этой работы нет такой настройки — пропущен.
link-unknown-near = Элемент ссылки { $item }: у этой работы нет такой настройки; может быть, «{ $label }»? — пропущен.
link-not-a-number = Элемент ссылки { $item }: для «{ $label }» нужно число — оставлено { $kept }.
link-out-of-range = Элемент ссылки { $item }: «{ $label }» — от { $range } — оставлено { $kept }.
link-not-whole = Элемент ссылки { $item }: «{ $label }» принимает целое число — оставлено { $kept }.
link-no-option = Элемент ссылки { $item }: «{ $label }» — одно из: { $range } — оставлено { $kept }.
link-malformed = Элемент ссылки { $item }: не в виде имя=значение — пропущен.
link-fault-no-such-lab = такой работы нет (есть: { $ids })
link-fault-no-such-lesson = такого урока нет (есть: { $ids })
link-fault-step-without-lesson = шаг задаётся только вместе с уроком (lesson=<работа>)
link-fault-no-such-step = шаг должен быть целым числом от 1 до { $steps }
link-fault-not-key-value = ожидается имя=значение
link-fault-seed = зерно должно быть целым числом ≥ 0
link-fault-speed = скорость должна быть от { $lo } до { $hi }
link-fault-presenter = для presenter (режим для проектора) нужно 1 или 0
link-fault-theme = для theme (оформление) нужно light или dark
link-fault-lang = для lang (язык) нужно en или ru
link-fault-embed = для embed (встраивание) нужно 1 или 0
link-fault-origin = `{ $text }` — не адрес сайта (origin): нужно вроде https://example.org или http://127.0.0.1:8000, или *
link-fault-at = для at нужно время в секундах ≥ 0
link-fault-what-if = `{ $text }` — не «а что если»: нужно время в секундах, затем изменения (вроде 1390:q_scale=0.1,x=2)
link-fault-too-many-what-ifs = не больше { $most } вариантов «а что если»
link-fault-answers-without-lesson = ответы задаются только вместе с уроком (lesson=<работа>)
link-fault-no-lesson = у этой работы нет урока
link-fault-not-an-answer = «{ $part }» — не номер шага с буквой ответа (например, 2b)
link-fault-no-such-answer = у шага { $step } нет ответа { $letter }
link-fault-not-a-parameter = «{ $key }» — не настройка работы { $lab } (и не «all»)

## Значение, которое ползунок или выбор единиц записи не принял (прогон идёт без изменений)
param-out-of-range = «{ $label }»: допустимо { $range }, { $given } вне этих пределов; значение не изменено.
param-not-a-number = Для «{ $label }» нужно число, а «{ $given }» — не число; значение не изменено.
param-not-finite = Для «{ $label }» нужно конечное число; значение не изменено.
param-not-whole = «{ $label }» принимает только целые числа, а { $given } — не целое; значение не изменено.
param-no-option = «{ $label }» — одно из: { $range }; «{ $given }» не совпадает ни с одним из них; значение не изменено.
param-unknown = В этой работе нет настройки «{ $key }».
param-malformed = «{ $text }» не имеет вида имя=значение.

## Командная строка: `attlab labs --lang`
cli-paper = статья
cli-default = по умолчанию

## Слова на видах
sphere-pole = S (полюс w)
phase-title = Фазовый портрет: скорость от угла (недавний след)
phase-angle = угол [°]
phase-rate = скорость [°/с]
body-unobservable = ненаблюдаемая ось
body-orbit = орбита
body-shadow = тень
body-no-gpu = 3D-виду нужен отрисовщик wgpu

## Масштаб и возврат
plot-reset-hint = Снова показать весь прогон (колесо масштабирует вокруг указателя, перетаскивание сдвигает; двойной щелчок делает то же)
plot-steady-note = масштаб по установившейся части: первые { $s } с выходят за него (колесо или щипок уменьшают)
view-reset-hint = Вернуть исходный вид (двойной щелчок делает то же)

## The lesson card (web/src/panels/lesson.rs)
lesson-start = ▶ Начать урок
lesson-step = шаг { $n } из { $count }
lesson-predict = Выберите, что вы ожидаете; затем расчёт это покажет.
lesson-shows = Расчёт показывает: { $answer }
lesson-running = Расчёт идёт до t = { $t } с…
lesson-back = ◀ Назад
lesson-next = Далее ▶
lesson-again = ⟲ Заново
lesson-end = Закончить урок
msg-lesson-bad-step = Этот шаг урока не открывается: { $why }
share = Поделиться…
cycle-open = Цикл фильтра
share-hint = Ссылка для группы: это состояние или этот шаг урока, со скрытыми или закреплёнными регуляторами, и её QR-код.
share-title = Поделиться с группой
share-scan = Наведите камеру телефона.
share-copy = Копировать ссылку
share-embed = Встроить в слайд или страницу курса
share-embed-hint = <iframe> с этим состоянием без панелей страницы (embed=1), 960×540, как слайд. Страница-хозяин может управлять им через postMessage: см. docs/embed.md.
share-copy-embed = Копировать код для встраивания
share-from-step = Этот шаг урока, с начала
share-as-is = Страница как есть
share-answers = С выбранными ответами
share-presenter = Открыть в режиме презентации
share-controls = Скрыть или закрепить регуляторы
share-control = Регулятор
share-hide = Скрыть
share-lock = Закрепить
share-all = Все регуляторы
cycle-title = Цикл фильтра
cycle-at = t = { $t } с, шаг { $k }
cycle-step = Шаг на один отсчёт (s)
cycle-pause = Пауза
cycle-states = Состояния: { $names }
cycle-no-update = На этом шаге измерения нет: x̂⁺ = x̂⁻, P⁺ = P⁻.
cycle-note-window = Окно адаптации закончилось: P заменена оценкой по окну (§2.6, табл. 2.3).
tile-none = —
lesson-bar = Урок · шаг { $n } из { $count }
note-string-holds = Эта нить держит { $mass } кг с запасом прочности { $factor } (§3.1 требует { $required }: d ≥ { $dmin } мм).
note-string-too-thin = Слишком тонкая для { $mass } кг: запас прочности { $factor }, меньше требуемого в §3.1 { $required } (d ≥ { $dmin } мм).
note-string-period = Нить и тело дают T = { $period } с.
note-p2-tuned-q-table3 = Работает с q_Λ = { $att }, q_ω = { $rate }, q_bias = { $bias } (с масштабом Q); таблица 3 даёт этому набору { $paper_att }, { $paper_rate }, { $paper_bias }.
note-p2-tuned-q-uncertain = Работает с q_Λ = { $att }, q_ω = { $rate }, q_bias = { $bias } (с масштабом Q); строка набора при ×1: { $paper_att }, { $paper_rate }, { $paper_bias } — таблица 3 в прочтении OCR, в некоторых цифрах неуверенном.
note-p2-tuned-q-ours = Работает с q_Λ = { $att }, q_ω = { $rate }, q_bias = { $bias } (с масштабом Q); строка набора при ×1: { $paper_att }, { $paper_rate }, { $paper_bias } — наш выбор (OCR потерял значения таблицы 3).
note-p0-limited = P₀ была бы вырожденной или неопределённой (b₀² ≥ a₀c₀): фильтры берут b₀ = ±{ $limit } град²/с, корреляцию 0,99.
note-u0-range = Ур. 4: u₀ лежит в [{ $lo }, { $hi }] рад/с²; этому стенду нужно { $needed } рад/с².

## До запуска приложения: копия этих строк в index.html (тест проверяет, что они совпадают)
boot-loading = Загрузка Attitude Lab…
boot-failed = Attitude Lab не удалось запустить
boot-failed-why = Либо файлы страницы не загрузились, либо в этом браузере нет WebAssembly или WebGL2. Перезагрузите страницу или откройте её в свежей версии Chrome, Firefox или Safari.
boot-no-script = Для Attitude Lab нужен JavaScript: включите его и перезагрузите страницу.

## Слова единиц (i18n::unit): каждое слово единицы, как её пишет код (`N·m`, `deg/s`),
## показывается так, как здесь; знаки между ними (·, /, ², √) остаются.
unit-deg = °
unit-s = с
unit-ms = мс
unit-min = мин
unit-h = ч
unit-Hz = Гц
unit-rad = рад
unit-kg = кг
unit-m = м
unit-mm = мм
unit-km = км
unit-N = Н
unit-nT = нТл
unit-ug = мкg
unit-bit = бит
unit-J = Дж
unit-mJ = мДж

## Ошибки: почему не удался прогон, повторный прогон, экспорт, оценка или точка перебора
## ({ $why } сообщений выше). У каждого вида каждой ошибки здесь есть слова (i18n::errors).
error-stats-empty = не из чего было вычислять: значений нет
error-stats-nan = значение { $index } — не число
error-score-columns = оценке нужно рядов: { $expected }, а получено: { $got }
error-score-empty-run = в прогоне нет отсчётов
error-score-diverged = ошибка настроенного фильтра — не число (фильтр разошёлся)
error-score-no-step = ступенька уставки равна 0°, поэтому измерять нечего: переходного процесса нет
error-score-ends-too-soon = прогон кончается на { $end } с — слишком скоро после ступеньки на { $step } с
error-score-few-samples = только в { $n } отсчётах есть и θ̂, и угол по акселерометру
error-score-stat = не удалось вычислить { $of ->
        [mse] СКО
        [t-tr] время переходного процесса t_tr
        [offset-before] смещение до ступеньки
        [offset-after] смещение после ступеньки
        [noise] шум
        [rms] СКЗ
       *[jitter] дрожание
    }: { $why }
error-score-count = оценка дала чисел: { $got }, а оценок названо: { $expected }
error-score-seed = зерно { $seed }: { $why }
error-sim-series = работа не записывает ряд «{ $name }»
error-sim-few-samples = в журнале нужно хотя бы два отсчёта с возрастающим временем
error-sim-refused = изменение { $change } на шаге { $step } отвергнуто при повторном прогоне: { $why }
error-sim-csv = не удалось записать CSV: { $detail }
error-sweep-wrong-lab = обработчику передано задание работы { $job } для работы { $lab }
error-sweep-no-sweep = у работы { $lab } нет перебора номер { $sweep }
error-sweep-no-point = у перебора номер { $sweep } нет точки { $point }
error-lesson-no-preset = шаг называет набор «{ $preset }», которого у работы { $lab } нет
error-lesson-preset = набор шага «{ $preset }» задаёт значение, которое работа отвергает: { $why }
error-worker-bad-job = обработчик не смог прочитать задание ({ $detail })
error-worker-no-lab = в сборке обработчика нет работы { $detail }
error-worker-unreadable = не удалось прочитать ответ обработчика ({ $detail })
error-worker-threw = обработчик сломался: { $detail }
error-worker-could-not-start = обработчик не смог запуститься или загрузить код страницы { $detail }
error-qr-too-long = ссылка слишком длинная для QR-кода ({ $bytes } байт): уберите из неё что-нибудь
error-qr-other = для этой ссылки нет QR-кода: { $detail }

## Страница, встроенная в другую (embed=1), и сообщения страницы-хозяина (docs/embed.md).
embed-time = t = { $t } с
embed-open = Открыть в Attitude Lab ↗
embed-open-hint = { $lab }: это состояние на целой странице, в новой вкладке.
host-must-value = числом или названием варианта
host-error-not-json = Сообщение — не JSON (разбор обрывается на строке { $line }, в столбце { $column }; 0 — если это значение, которое JSON не выражает).
host-error-not-attlab = Сообщение не для Attitude Lab: в нём нужны "api": 1 и "type".
host-error-api-version = Эта страница понимает API версии { $api }, а сообщение просит { $version }.
host-error-unknown-type = Нет сообщения типа «{ $type }» (их список — в docs/embed.md).
host-error-bad-argument = «{ $name }» должно быть { $must }.
host-error-bad-parameter = { $why }
host-error-locked = Ссылка блокирует «{ $label }»: значение не меняется.
host-error-no-preset = В этой лаборатории нет набора «{ $id }».
host-error-no-lab = Нет лаборатории «{ $id }».
host-error-no-lesson = В этой лаборатории нет урока.
host-error-no-step = В уроке нет шага «{ $id }».
host-error-no-question = На этом шаге нет вопроса.
host-error-no-answer = У вопроса нет ответа { $answer }.
host-error-origin-not-allowed = Страница { $origin } не может управлять этой: ссылка должна разрешить её через origin={ $origin }.
host-must-string = строкой
host-must-params = объектом из ключей параметров и значений
host-must-positive = положительным числом
host-must-step = номером шага от 1 или его id
host-must-answer = номером ответа от 1

## О программе и как ссылаться (конец панели управления).
about-title = О программе и как ссылаться
about-build = Attitude Lab { $version }, коммит { $commit }, сборка { $date }.
about-cite = Как сослаться на программу
about-cite-software = The Attitude Lab contributors (2026). Attitude Lab, версия { $version } (коммит { $commit }) [программа]. MIT или Apache-2.0. Файл CITATION.cff в репозитории даёт эту ссылку и ссылки на статьи.
about-papers = Статьи, которые воспроизводят лаборатории
about-teacher-notes = Записки для преподавателя к этому уроку (для печати)
about-licence = Свободная программа под лицензией MIT или Apache-2.0.
