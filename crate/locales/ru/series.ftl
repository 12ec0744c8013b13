# Слова, из которых складываются подписи рядов (crate/src/i18n/series.rs): кто записывает
# ряд, и величины, которые даёт ковариация каждого фильтра. Состояния — в родительном
# падеже: они стоят после «дисперсия» и «ковариация».

series-time = время t
owner-truth = Истина
owner-sensors = Датчики
series-variance = дисперсия { $state }
series-covariance = ковариация { $a } и { $b }
series-nees = NEES ориентации eᵀP⁻¹e
series-health = состояние (0 = норма)

## Состояние ковариации, как его называют дисперсия и ковариация
state-attitude-axis = ориентации вокруг { $axis }
state-rate-axis = угловой скорости вокруг { $axis }
state-gyro-bias-axis = смещения гироскопа вокруг { $axis }
state-mag-bias-axis = смещения магнитометра вдоль { $axis }
state-mag-turn-axis = смещения магнитометра как поворота поля вокруг { $axis }
state-angle = угла
state-rate = угловой скорости
