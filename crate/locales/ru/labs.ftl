# Переводы слов, которые задают сами работы (их английский текст — в коде работы, он же
# запасной). Идентификатор выводится из работы: lab-<id>-title — название в списке работ,
# lab-<id>-summary — её описание.
# Тест падает, если у зарегистрированной работы нет перевода названия или если здесь есть
# идентификатор, которого ни одна работа не выводит.

lab-free-rotation-title = Свободное вращение (интегрирование гироскопа)
lab-free-rotation-paper = Базовая лаборатория; кинематика статьи 3 (Матвеев и др., 2025), ур. 21
lab-p1-title = Статья 1: макет на подвесе, одноосный гироскоп
lab-p1-paper = Иванов, Овчинников, одноосный гироскоп и подвешенный макет, препринт ИПМ им. М. В. Келдыша РАН
lab-p2-title = Статья 2: TabletSat, двенадцать наборов датчиков
lab-p2-paper = Иванов, Ивлев, Карпенко, Овчинников, определение ориентации микроспутников TabletSat, препринт ИПМ им. М. В. Келдыша 2014-64
lab-p3-title = Статья 3: (w, z) на сфере Римана
lab-p3-paper = Матвеев и др., Приборы и методы измерений 2025;16(3):202–211
lab-p4-title = Статья 4: крен квадрокоптера, фильтр Калмана с γ = det Q/det R
lab-p4-paper = Фам, Шилин, Гирник, Нгуен, синтез фильтра Калмана для несимметричного квадрокоптера, Инженерный вестник Дона 2025 № 10
lab-p5-title = Статья 5: коррекция угловых скоростей по матрице чувствительности
lab-p5-paper = Башняков, Пичкур, Полищук, Линдер, адаптивная коррекция угловых скоростей через матрицу чувствительности

# lab-<id>-summary — «Что я вижу?»: что моделирует работа и что в ней двигать.

lab-free-rotation-summary = Твёрдое тело кувыркается без внешнего момента (уравнения Эйлера). Трёхосный гироскоп измеряет его угловую скорость с шумом и смещением нуля, а две оценки интегрируют гироскоп: кватернион (q̇ = ½ q⊗ω) и параметры (u, v, z) статьи 3 (ур. 21), которые переходят к перевёрнутой карте s = 1/w, когда тело оказывается вверх дном. Без шума и смещения обе оценки идут за истиной; ползунок смещения уводит обе одинаково, ползунок шума добавляет случайное блуждание. Ползунки моментов инерции меняют движение сразу; закрутка, ось и наклон вступают в силу при сбросе.
lab-p1-summary = Тело висит на тонкой нити и закручивается вокруг вертикали: Iφ̈ = −fφ − демпфирование, где f = G·I_p/L и I_p = πd⁴/32, так что T = 2π√(I/f). Единственный датчик — одноосный гироскоп (шум, квантование, диапазон, усреднение до частоты фильтра). Три оценки: прямое интегрирование (φ_int); фильтр Калмана в предположении постоянного вращения (φ̈ = 0); фильтр в предположении крутильных колебаний (Ω = 2π/T — задайте ошибку периода, чтобы увидеть неверную модель). Без адаптации (N = 0, Q = 0) P схлопывается, коэффициент усиления уходит в ноль и фильтры перестают слушать датчик. Согласование ковариаций переносит разброс последних N отсчётов в P: в статье лучше всего N ≈ 100, при N = 1000 хуже, при N > 2000 плохо. Графики ошибок статьи сравнивают фильтры с φ_int (в её опытах истины нет); относительно истинного угла ни один фильтр не превзойдёт проинтегрированный шум гироскопа σ√(t/f), потому что один датчик угловой скорости не делает угол наблюдаемым — здесь показаны оба графика ошибок. По умолчанию — условия статьи: 100 Гц, R = σ², T ≈ 400 с и ζ = 0,05 (ни того, ни другого статья не указывает; см. готовые наборы). Возмущения: импульс момента, маятниковое качание, проникающее в гироскоп, тряска подвеса, неверный начальный угол.
lab-p2-summary = Микроспутник массой 20 кг на круговой орбите удерживает орбитальную систему координат (e₃ вверх, e₂ по нормали к орбите) маховиками против гравитационного момента и неучтённого возмущения. Четыре вида датчиков — магнитометр (поле по модели WMM NOAA), пять головок солнечного датчика, гироскоп со смещением, звёздный датчик, который теряет ориентацию выше 2 °/с и вблизи Солнца или Земли, — питают сразу все расширенные фильтры Калмана таблицы 2 статьи: один и тот же мультипликативный фильтр со строками своего набора датчиков, с оценкой смещения гироскопа или магнитометра, укороченный вариант [λ, Δω], параллельный фильтр возмущения (с затуханием α) и фильтр с постоянным коэффициентом. Точность в статье — √max diag P∞; рядом — измеренная σ за последнюю минуту и NEES относительно границ χ², по которым видно, какой фильтр слишком себе доверяет. Статья не даёт ни орбиты, ни коэффициентов маховиков, ни частот датчиков, ни P₀: по умолчанию — солнечно-синхронная орбита 600 км, датчики на 1 Гц, прогноз фильтров на 10 Гц (частоты, при которых подходит Q статьи), и всё это — ползунки. Готовые наборы: ошибка модели, ослеплённый звёздный датчик, длинная тень, орбита без тени, гироскоп и один вектор. Вид в 3D рисует от тела направления на Солнце, поле и надир, ненаблюдаемую ось фильтра-призрака, если она есть, и орбиту со стороны нормали с тенью Земли; таблица слева даёт σ каждого фильтра за последнюю минуту и его собственное √P рядом с таблицей 3 статьи (щелчок по строке делает фильтр призраком).
lab-p3-summary = Вертикаль, видимая из тела, k = (a′, b′, c′), спроецированная из полюса S на плоскость тела, даёт w = u + jv = (a′ + jb′)/(1 + c′) (ур. 12); z — поворот вокруг вертикали, A = A(w)·A(z). Гироскоп задаёт u̇ = vω_ζ + uvω_ξ − ½ω_η(1 + u² − v²), v̇ = −uω_ζ − uvω_η + ½ω_ξ(1 − u² + v²), ż = ω_ζ + uω_ξ + vω_η (ур. 21) — (u, v) без z. Акселерометры дают uᵃ = n_ξ/(1 + n_ζ), vᵃ = n_η/(1 + n_ζ) (ур. 28) без интегрирования. Канал гироскопа уходит со смещением, канал акселерометров шумит и обманывается боковым толчком; смешение wᵏ = HPF(w) + LPF(wᵃ) с постоянной времени T берёт лучшее от обоих, а фильтр Калмана сам выбирает коэффициент по уровням шума (его эллипс 3σ нарисован на плоскости и на сфере). Смещение, шум, толчок, T и масштаб фильтра действуют сразу; ползунки движения — при сбросе. Медленное кувыркание переворачивает тело вверх дном: смотрите, как карта переходит к s = 1/w.
lab-p4-summary = Стенд поворачивается вокруг одной оси: испытательный стенд статьи (рычаг на подшипнике с одним двигателем, рис. 3) или квадрокоптер с разными плечами и двигателями (ур. 2), так что для удержания любого угла нужна постоянная команда u₀ ≠ 0. Регулятор — вложенный P–PI рис. 1 или обычный ПИД — делит команду на интегральную u₀ и переменную u_v с нулевым средним. MPU-6050 (шум по паспорту, смещение нуля, 16-битные отсчёты, диапазоны) измеряет угловую скорость и — через atan2 от акселерометра — угол, неверный, пока стенд быстро движется. Фильтр Калмана статьи на [θ, ω] получает u_v и настраивается одним числом γ = det Q / det R: малое γ доверяет модели (гладко, но со смещением и медленным переходным процессом), большое — датчикам (шумно). Рядом — комплементарный фильтр (база сравнения в статье) и, сверх статьи, фильтр с оценкой смещения гироскопа и фильтр, знающий u₀. Статья не даёт параметров объекта: рычаг (J = 2·10⁻³ кг·м², плечо 0,2 м), квадрокоптер (J = 0,01 кг·м², плечи 0,12 м, тяга зависания 2,45 Н на двигатель), контур 100 Гц, коэффициенты регулятора, связь γ → Q (Q = q·diag(dt³/3, dt), det Q = γ det R, R по паспорту) и полоса 5 % для времени переходного процесса — наши. Как на рис. 1, регулятор работает по оценке θ̂ фильтра, настроенного по γ, поэтому шумная или запаздывающая оценка двигает сам стенд; переключите его на истинный угол, чтобы сравнить все фильтры на одном движении. Перебор ниже повторяет опыт настройки статьи: J = α·MSE + β·t_tr в зависимости от γ для трёх пар (α, β) (5 зёрен, медианы, минимум обведён), карта Q по двум элементам Q с линиями γ и, при воспроизведении записи, перебор γ по записи. `attlab reproduce p4` измеряет таблицу 1.
lab-p5-summary = Измеренные угловые скорости ω задают кватернион, 2Λ̇ = Λ ∘ (ω + p), с аддитивной поправкой p. Рядом с Λ интегрируется чувствительность U = ∂Λ/∂p (4×3), обнуляемая при каждой опорной ориентации. В каждой опорной ориентации (каждые Δt) p делает один шаг Гаусса–Ньютона h = (UᵀQU + εI)⁻¹UᵀQ(Λ_ref − Λ). Метод (9) продолжает состояние и — после линеаризации его шаг имеет определитель 1, оба собственных числа на единичной окружности — колеблется бесконечно: впервые попадает в допуск сразу после 2Δt и снова его покидает. Метод (10) добавляет ε, (11) подбирает длину шага на заново проинтегрированном интервале; сверх статьи — повторное интегрирование последнего интервала с новым p сходится за несколько интервалов. Диаграмма показывает собственные числа для текущих Δt и ε. При смещённом гироскопе p сходится к −b; при потере опорной ориентации исправленное интегрирование идёт само и снова сходится, когда она возвращается. Выходной файл — как в статье: строки (t, угол₁, угол₂, угол₃) до первой строки в пределах допуска.

# lab-<id>-param-<key> — подпись ползунка; lab-<id>-param-<key>-option-<n> — вариант выбора.

lab-free-rotation-param-inertia_x_kg_m2 = Момент инерции Ixx
lab-free-rotation-param-inertia_y_kg_m2 = Момент инерции Iyy
lab-free-rotation-param-inertia_z_kg_m2 = Момент инерции Izz
lab-free-rotation-param-spin_deg_s = Начальная закрутка
lab-free-rotation-param-spin_axis = Ось закрутки
lab-free-rotation-param-spin_axis-option-0 = x (наименьший I: устойчиво)
lab-free-rotation-param-spin_axis-option-1 = y (средний I: кувыркается)
lab-free-rotation-param-spin_axis-option-2 = z (наибольший I: устойчиво)
lab-free-rotation-param-tilt_deg = Начальный наклон
lab-free-rotation-param-gyro_noise_deg_s = Шум гироскопа σ
lab-free-rotation-param-gyro_bias_deg_s = Смещение нуля гироскопа
lab-free-rotation-param-gyro_walk_deg_s_sqrt_s = Случайное блуждание смещения
lab-free-rotation-param-rate_hz = Частота отсчётов

lab-p1-param-string_material = Материал нити
lab-p1-param-string_material-option-0 = сталь (G = 80 ГПа)
lab-p1-param-string_material-option-1 = титановый сплав (41 ГПа)
lab-p1-param-string_material-option-2 = вольфрам (161 ГПа)
lab-p1-param-string_material-option-3 = нейлон (1 ГПа)
lab-p1-param-string_diameter_mm = Диаметр нити d
lab-p1-param-string_length_m = Длина нити L
lab-p1-param-inertia_kg_m2 = Момент инерции тела I
lab-p1-param-body_mass_kg = Масса тела M
lab-p1-param-body_model = Модель тела
lab-p1-param-body_model-option-0 = 1 степень свободы: только кручение, качание задано (§3.3, модель фильтров)
lab-p1-param-body_model-option-1 = 5 степеней свободы: тело качается на свободной точке подвеса (§3.2, ур. 3.2)
lab-p1-param-com_offset_mm = Центр масс ниже нити на d
lab-p1-param-tilt_inertia_kg_m2 = Момент инерции наклона A = B
lab-p1-param-period_from = Период крутильных колебаний T
lab-p1-param-period_from-option-0 = по нити и телу
lab-p1-param-period_from-option-1 = задан вручную
lab-p1-param-typed_period_s = Заданный период T
lab-p1-param-damping_ratio = Коэффициент затухания ζ
lab-p1-param-initial_angle_deg = Начальный угол φ₀
lab-p1-param-initial_rate_deg_s = Начальная угловая скорость
lab-p1-param-init_error_deg = Начальная ошибка угла у фильтров
lab-p1-param-p0_a_deg2 = P₀: дисперсия угла a₀
lab-p1-param-p0_b_deg2_s = P₀: ковариация b₀
lab-p1-param-p0_c_deg2_s2 = P₀: дисперсия скорости c₀
lab-p1-param-gyro_noise_deg_s = Шум гироскопа σ
lab-p1-param-gyro_range_deg_s = Диапазон гироскопа ±
lab-p1-param-gyro_bits = Разрядность гироскопа
lab-p1-param-input_rate_hz = Частота выдачи гироскопа
lab-p1-param-filter_rate_hz = Частота фильтра
lab-p1-param-kf_window = Окно адаптации N
lab-p1-param-kf_adaptation = Адаптация
lab-p1-param-kf_adaptation-option-0 = пила: P := mean q qᵀ, q = (φ_int − φ̂, z − φ̇̂) (прочтение этого проекта)
lab-p1-param-kf_adaptation-option-1 = пила, только диагональ mean q qᵀ (устойчиво при малых N)
lab-p1-param-kf_adaptation-option-2 = буквально: P := mean (K r)(K r)ᵀ (схлопывается)
lab-p1-param-kf_adaptation-option-3 = шум процесса Q по скорости из окна
lab-p1-param-kf_adapt_r = Адаптировать и R
lab-p1-param-kf_period_error_pct = Ошибка периода у крутильного фильтра
lab-p1-param-impulse_time_s = Импульс момента в момент
lab-p1-param-impulse_deg_s = Величина импульса (скачок скорости)
lab-p1-param-swing_amp_deg = Маятниковое качание
lab-p1-param-swing_misalign_deg = Перекос гироскопа
lab-p1-param-shake_torque_n_m = Тряска подвеса (σ момента)

lab-p2-param-altitude_km = Высота орбиты
lab-p2-param-inclination_deg = Наклонение
lab-p2-param-ltan_h = Местное время восходящего узла
lab-p2-param-day_of_year = День 2026 года
lab-p2-param-arg_lat0_deg = Начало: аргумент широты
lab-p2-param-init_att_err_deg = Начальное отклонение от орбитальной системы
lab-p2-param-init_rate_err_deg_s = Начальное отклонение скорости от орбитальной
lab-p2-param-k_att = Коэффициент маховиков K_λ
lab-p2-param-k_rate = Коэффициент маховиков K_ω
lab-p2-param-dist_torque_n_m = Неучтённый момент
lab-p2-param-dist_from_s = Момент включается в
lab-p2-param-mag_noise_nt = σ магнитометра
lab-p2-param-mag_bias_nt = Смещение магнитометра
lab-p2-param-mag_turn_deg = Смещение магнитометра как поворот поля
lab-p2-param-onboard_field = Бортовая модель поля
lab-p2-param-onboard_field-option-0 = WMM, как в истине (без ошибки модели)
lab-p2-param-onboard_field-option-1 = наклонный диполь (несколько мкТл ошибки)
lab-p2-param-onboard_field-option-2 = WMM + ошибка модели заданного ниже размера
lab-p2-param-model_error_nt = Ошибка модели
lab-p2-param-sun_noise_deg = σ солнечного датчика
lab-p2-param-sun_fov_deg = Поле зрения головки солнечного датчика ±
lab-p2-param-gyro_noise_deg_s = σ гироскопа
lab-p2-param-gyro_bias_deg_s = Смещение гироскопа
lab-p2-param-gyro_walk_deg_s_sqrt_s = Случайное блуждание смещения гироскопа
lab-p2-param-star_noise_deg = σ звёздного датчика
lab-p2-param-star_reading = σ звёздного датчика — это
lab-p2-param-star_reading-option-0 = 0,001° на ось поворота
lab-p2-param-star_reading-option-1 = 0,001° на каждую компоненту кватерниона (поворот 0,002°)
lab-p2-param-star_max_rate_deg_s = Звёздный датчик теряется выше
lab-p2-param-star_sun_exclusion_deg = Зона засветки Солнцем у звёздного датчика
lab-p2-param-star_earth_exclusion_deg = Зона засветки лимбом Земли у звёздного датчика
lab-p2-param-predict_rate_hz = Частота прогноза фильтров
lab-p2-param-vector_rate_hz = Частота магнитометра и солнечного датчика
lab-p2-param-gyro_rate_hz = Частота гироскопа
lab-p2-param-star_rate_hz = Частота звёздного датчика
lab-p2-param-q_scale = Масштаб Q (все фильтры)
lab-p2-param-alpha = Затухание α фильтра возмущения
lab-p2-param-rd_scale = Масштаб R_d фильтра возмущения
lab-p2-param-freeze_after_s = Фильтры с постоянным усилением: коэффициент замораживается в
lab-p2-param-filter_init_err_deg = Начальная ошибка ориентации у фильтров
lab-p2-param-tune_set = Настраиваемый набор
lab-p2-param-tune_set-option-0 = 1 ЗД+ДУС+Маг+СД [λ,ω]
lab-p2-param-tune_set-option-1 = 2 ЗД+ДУС+Маг [λ,ω]
lab-p2-param-tune_set-option-2 = 3 ЗД+Маг+СД [λ,ω]
lab-p2-param-tune_set-option-3 = 4 ЗД+Маг [λ,ω,Δb]
lab-p2-param-tune_set-option-4 = 5 Маг+СД+ДУС [λ,ω]
lab-p2-param-tune_set-option-5 = 6 Маг+СД+ДУС [λ,ω,Δω]
lab-p2-param-tune_set-option-6 = 7 Маг+СД+ДУС [λ,ω,Δb]
lab-p2-param-tune_set-option-7 = 8 ЗД+ДУС [λ,ω]
lab-p2-param-tune_set-option-8 = 9 ЗД+ДУС [λ,ω,Δω]
lab-p2-param-tune_set-option-9 = 10 Маг+СД [λ,ω]
lab-p2-param-tune_set-option-10 = 11 Маг+ДУС [λ,ω]
lab-p2-param-tune_set-option-11 = 12 ЗД [λ,ω]
lab-p2-param-tune_q_att = Настраиваемый набор: q_Λ ×
lab-p2-param-tune_q_rate = Настраиваемый набор: q_ω ×
lab-p2-param-tune_q_bias = Настраиваемый набор: q_bias ×
lab-p2-param-sun_along_field = Мысленный опыт: Солнце вдоль поля
lab-p2-param-sun_field_angle_deg = Угол Солнце — поле

lab-p3-param-profile = Движение
lab-p3-param-profile-option-0 = статья 3: рыскание с постоянной скоростью, гармонические тангаж и крен
lab-p3-param-profile-option-1 = коническое (тангаж и крен со сдвигом 90°)
lab-p3-param-profile-option-2 = медленное кувыркание (переворачивается вверх дном)
lab-p3-param-profile-option-3 = свободное вращение (без момента)
lab-p3-param-roll_amp_deg = Амплитуда крена A_γ
lab-p3-param-pitch_amp_deg = Амплитуда тангажа A_ϑ
lab-p3-param-yaw_rate_deg_s = Скорость рыскания ω_ψ
lab-p3-param-pitch_freq_rad_s = Частота тангажа ω_ϑ
lab-p3-param-roll_freq_rad_s = Частота крена ω_γ
lab-p3-param-tumble_rate_deg_s = Скорость кувыркания по крену
lab-p3-param-gyro_bias_deg_s = Смещение гироскопа
lab-p3-param-bias_axes = Смещение по осям
lab-p3-param-bias_axes-option-0 = всем трём (+, +, +)
lab-p3-param-bias_axes-option-1 = только ξ
lab-p3-param-bias_axes-option-2 = только η
lab-p3-param-bias_axes-option-3 = только ζ
lab-p3-param-bias_axes-option-4 = чередуясь (+, −, +)
lab-p3-param-gyro_noise_deg_s = Шум гироскопа σ
lab-p3-param-accel_noise_g = Шум акселерометра σ
lab-p3-param-bump_g = Боковой толчок
lab-p3-param-bump_time_s = Время толчка
lab-p3-param-blend_time_const_s = Постоянная времени смешения T
lab-p3-param-kf_q_scale = Масштаб шума процесса фильтра
lab-p3-param-rate_hz = Частота отсчётов

lab-p4-param-rig = Стенд
lab-p4-param-rig-option-0 = испытательный стенд: рычаг с одной степенью свободы, один двигатель (рис. 3)
lab-p4-param-rig-option-1 = крен квадрокоптера, симметричного (ур. 3)
lab-p4-param-rig-option-2 = крен квадрокоптера с несимметричными плечами и двигателями (ур. 2)
lab-p4-param-asymmetry_pct = Асимметрия a
lab-p4-param-geometry_uncertainty_pct = Геометрия известна с точностью ±
lab-p4-param-lever_torque_n_m = Момент веса рычага M_g
lab-p4-param-motor_tau_s = Запаздывание двигателя T
lab-p4-param-loop_on = Регулятор работает по
lab-p4-param-loop_on-option-0 = θ̂, ω̂ фильтра, настроенного по γ (рис. 1 статьи)
lab-p4-param-loop_on-option-1 = истинным θ, ω (все фильтры на одном движении)
lab-p4-param-loop_on-option-2 = θ̂, ω̂ комплементарного фильтра
lab-p4-param-loop_on-option-3 = θ̂, ω̂ фильтра Калмана с оценкой смещения
lab-p4-param-loop_on-option-4 = θ̂, ω̂ фильтра Калмана со входом u_v + u₀
lab-p4-param-controller = Регулятор
lab-p4-param-controller-option-0 = вложенный P–PI (рис. 1)
lab-p4-param-controller-option-1 = обычный ПИД
lab-p4-param-bandwidth_rad_s = Полоса регулятора ω_c
lab-p4-param-setpoint_deg = Ступенька уставки
lab-p4-param-step_period_s = Ступеньки каждые
lab-p4-param-gust_rad_s2 = Порыв / толчок
lab-p4-param-gust_at_s = Порыв в момент
lab-p4-param-sample_hz = Частота отсчётов
lab-p4-param-dlpf_hz = Полоса фильтра DLPF MPU-6050
lab-p4-param-gyro_range = Диапазон гироскопа
lab-p4-param-gyro_range-option-0 = ±250 °/с (при включении)
lab-p4-param-gyro_range-option-1 = ±500 °/с
lab-p4-param-gyro_range-option-2 = ±1000 °/с
lab-p4-param-gyro_range-option-3 = ±2000 °/с
lab-p4-param-accel_range = Диапазон акселерометра
lab-p4-param-accel_range-option-0 = ±2 g (при включении)
lab-p4-param-accel_range-option-1 = ±4 g
lab-p4-param-accel_range-option-2 = ±8 g
lab-p4-param-accel_range-option-3 = ±16 g
lab-p4-param-gyro_density_deg_s = Спектральная плотность шума гироскопа
lab-p4-param-accel_density_ug = Спектральная плотность шума акселерометра
lab-p4-param-vibration_g = Вибрация винтов на датчике
lab-p4-param-gyro_offset_deg_s = Смещение нуля гироскопа
lab-p4-param-imu_offset_m = Расстояние датчика от оси
lab-p4-param-gamma = γ = det Q / det R
lab-p4-param-kf_q_from = Q фильтра из
lab-p4-param-kf_q_from-option-0 = γ (как в статье)
lab-p4-param-kf_q_from-option-1 = двух элементов
lab-p4-param-kf_q_angle_deg2 = Элемент Q по углу q_θ
lab-p4-param-kf_q_rate_deg2_s2 = Элемент Q по скорости q_ω
lab-p4-param-kf_input = Подавать u_v в фильтр
lab-p4-param-kf_sigma_angle_deg = R фильтра: σ угла по акселерометру
lab-p4-param-kf_sigma_rate_deg_s = R фильтра: σ гироскопа
lab-p4-param-kf_bias_walk = Фильтр со смещением: блуждание смещения
lab-p4-param-cf_gain = Коэффициент комплементарного фильтра a

lab-p5-param-profile = Движение
lab-p5-param-profile-option-0 = как в статье: постоянная ориентация, ω = 0
lab-p5-param-profile-option-1 = постоянная угловая скорость
lab-p5-param-profile-option-2 = гармоническая угловая скорость
lab-p5-param-rate_deg_s = Угловая скорость
lab-p5-param-rate_freq_rad_s = Частота гармоники
lab-p5-param-sequence = Последовательность углов
lab-p5-param-sequence-option-0 = z-y-x (Крылов, корабельные: рыскание, тангаж, крен)
lab-p5-param-sequence-option-1 = x-y-z
lab-p5-param-sequence-option-2 = y-x-z
lab-p5-param-sequence-option-3 = z-x-y
lab-p5-param-sequence-option-4 = x-z-y
lab-p5-param-sequence-option-5 = y-z-x
lab-p5-param-init_1_rad = Начальный угол 1
lab-p5-param-init_2_rad = Начальный угол 2
lab-p5-param-init_3_rad = Начальный угол 3
lab-p5-param-ref_1_rad = Опорный угол 1
lab-p5-param-ref_2_rad = Опорный угол 2
lab-p5-param-ref_3_rad = Опорный угол 3
lab-p5-param-interval_s = Интервал опорных ориентаций Δt
lab-p5-param-step_s = Шаг интегрирования
lab-p5-param-integration = Метод интегрирования
lab-p5-param-integration-option-0 = Рунге–Кутта 4
lab-p5-param-integration-option-1 = средней точки (Рунге–Кутта 2)
lab-p5-param-integration-option-2 = Эйлера
lab-p5-param-eps = Регуляризация ε
lab-p5-param-q_weight_0 = Вес Q₀₀ (λ₀)
lab-p5-param-q_weight_1 = Вес Q₁₁ (λ₁)
lab-p5-param-q_weight_2 = Вес Q₂₂ (λ₂)
lab-p5-param-q_weight_3 = Вес Q₃₃ (λ₃)
lab-p5-param-p0_x_deg_s = Начальное p по x
lab-p5-param-p0_y_deg_s = Начальное p по y
lab-p5-param-p0_z_deg_s = Начальное p по z
lab-p5-param-tolerance_rad = Допуск на угол
lab-p5-param-renormalise = Нормировать Λ на каждом шаге
lab-p5-param-gyro_bias_deg_s = Смещение гироскопа
lab-p5-param-gyro_noise_deg_s = Шум гироскопа σ
lab-p5-param-ref_noise_rad = Шум опорной ориентации σ
lab-p5-param-dropout_from_s = Опорная ориентация теряется в
lab-p5-param-dropout_s = Опорная ориентация потеряна на
lab-p5-param-output_method = Выходной файл метода
lab-p5-param-output_method-option-0 = (9) Гаусс–Ньютон
lab-p5-param-output_method-option-1 = (10) с регуляризацией
lab-p5-param-output_method-option-2 = (11) с подбором шага
lab-p5-param-output_method-option-3 = вариант с повторным интегрированием
lab-p5-param-output_method-option-4 = без коррекции

# lab-<id>-preset-<n> — название готового набора.

lab-p1-preset-vg-910d = VG-910D
lab-p1-preset-adis16100 = ADIS16100
lab-p1-preset-period-578 = T ≈ 578 с
lab-p1-preset-earlier-setting = прежняя настройка
lab-p1-preset-rocking-body = качающееся тело (5 степеней)
lab-p2-preset-no-model-error = без ошибки модели
lab-p2-preset-model-error-400 = ошибка модели 400 нТл
lab-p2-preset-star-tracker-blinded = звёздный датчик ослеплён
lab-p2-preset-noon-midnight = орбита полдень–полночь (длинная тень)
lab-p2-preset-dawn-dusk = орбита рассвет–закат (без тени)
lab-p2-preset-sun-along-field = Солнце ∥ поле
lab-p2-preset-gyro-one-vector = гироскоп + один вектор (уход)
lab-p2-preset-sensors-10hz = датчики на 10 Гц
lab-p2-preset-constant-gain = постоянный коэффициент усиления (§3.3)
lab-p2-preset-fig7-field-turn = рис. 7: смещение как поворот поля
lab-p4-preset-gamma-best = γ = 2·10⁻³: лучшее из четырёх значений статьи
lab-p4-preset-gamma-small = γ = 10⁻⁵: смещение, медленно
lab-p4-preset-gamma-large = γ = 0,2: шумно
lab-p4-preset-asymmetric = квадрокоптер, асимметрия 15 %
lab-p4-preset-fast-motion = быстрое движение обманывает акселерометр
lab-p4-preset-push = толчок на 6 с
lab-p4-preset-uncalibrated-gyro = некалиброванный гироскоп (смещение 5 °/с)
lab-p5-preset-paper-case = случай статьи, Δt = 1,17
lab-p5-preset-gyro-bias = смещение гироскопа 2 °/с
lab-p5-preset-reference-lost = опорная ориентация потеряна на 20–50 с

# lab-<id>-figure-<n> — вкладка графика, повторяющая рисунок статьи или показывающая своё.

lab-free-rotation-figure-attitude = Ориентация (рыскание, тангаж, крен)
lab-free-rotation-figure-errors = Ошибки ориентации (связанные оси)
lab-free-rotation-figure-energy-momentum = Энергия и кинетический момент (истина)
lab-p1-figure-angle = Угол
lab-p1-figure-rate = Угловая скорость
lab-p1-figure-angle-error-vs-int = Ошибка угла относительно φ_int (статья)
lab-p1-figure-angle-error = Ошибка угла относительно истины
lab-p1-figure-rate-error = Ошибка скорости относительно истины
lab-p1-figure-rate-error-vs-sensor = Ошибка скорости относительно датчика
lab-p1-figure-p-diagonal = P: a = P_φφ, c = P_φ̇φ̇ (log10)
lab-p1-figure-p-cross = P: b = P_φφ̇
lab-p2-figure-fig4-attitude = Ошибки ориентации ЗД+ДУС (рис. 4)
lab-p2-figure-fig5-rate = Ошибки скорости ЗД+ДУС (рис. 5)
lab-p2-figure-every-filter = Ошибка ориентации каждого фильтра
lab-p2-figure-fig6-gyro-bias = Смещение гироскопа: истина и оценки (рис. 6)
lab-p2-figure-fig7-mag-bias = Смещение магнитометра: истина и оценка (рис. 7)
lab-p2-figure-fig8-disturbance = Оценки возмущения против истинного (рис. 8, табл. 4)
lab-p2-figure-nees = Согласованность: NEES ориентации (χ²₃: 95 % в 0,22…9,35)
lab-p2-figure-p-diagonal = Диагональ P, ЗД+ДУС и Маг+СД+ДУС (log; ориентация рад², скорость рад²/с²)
lab-p2-figure-nis = NIS на каждом обновлении
lab-p2-figure-outages = Отказы: тень, Солнце видно, звёздный датчик
lab-p2-figure-wheel-momentum = Кинетический момент маховиков
lab-p2-figure-fig7-field-turn = Смещение магнитометра как поворот поля: истина и оценка (рис. 7)
lab-p2-figure-constant-gain = Постоянный коэффициент усиления против своего расширенного фильтра Калмана (§3.3, табл. 5)
lab-p3-figure-fig4-uv = Рис. 4: u, v
lab-p3-figure-fig4-z = Рис. 4: z
lab-p3-figure-fig5-angles = Рис. 5: рыскание, тангаж, крен
lab-p3-figure-fig8-v = Рис. 8: v, vᵃ
lab-p3-figure-fig10-filters = Рис. 10: HPF(v), LPF(vᵃ), vᵏ
lab-p3-figure-tilt-errors = Ошибки наклона
lab-p3-figure-kf-variances = Дисперсии фильтра Калмана (log10)
lab-p4-figure-roll = Крен: истина, уставка, угол по акселерометру и оценки
lab-p4-figure-roll-error = Ошибка крена каждого фильтра
lab-p4-figure-rate-error = Ошибка скорости каждого фильтра
lab-p4-figure-control = Управление: u_v, интегральная u₀ и u₀, нужная для зависания
lab-p4-figure-gyro = Гироскоп: показание и истина
lab-p4-figure-bias-kf = Фильтр со смещением (сверх статьи): оценка смещения гироскопа
lab-p5-figure-error = Ошибка ориентации (все методы)
lab-p5-figure-angles = Углы метода (9) и опорные
lab-p5-figure-correction-9 = Поправка p (9)
lab-p5-figure-correction-variant = Поправка p (вариант)
lab-p5-figure-condition = Число обусловленности UᵀQU
lab-p5-figure-singular-values = Сингулярные числа UᵀQU (9)
lab-p5-figure-step-size = Длина шага s метода (11)
lab-p5-figure-references = Получено опорных ориентаций
