# Единицы столбцов записи (в коде — коды, которые принимает CLI: `--rate-unit deg_s`), их
# подсказки, заголовок таблицы точности статьи 2, диаграмма статьи 5 и направления на 3D-виде.

lab-p1-param-rate_unit = столбец скорости
lab-p1-param-rate_unit-help = Единица столбца скорости: °/с, м°/с (лабораторная программа статьи) или рад/с.
lab-p1-param-rate_unit-option-0 = °/с
lab-p1-param-rate_unit-option-1 = м°/с (программа статьи)
lab-p1-param-rate_unit-option-2 = рад/с
lab-p1-param-time_unit = столбец времени
lab-p1-param-time_unit-help = Единица столбца времени: секунды или миллисекунды.
lab-p1-param-time_unit-option-0 = с
lab-p1-param-time_unit-option-1 = мс
lab-p4-param-accel_unit = столбцы акселерометра
lab-p4-param-accel_unit-help = Столбцы акселерометра: отсчёты диапазона ±2/4/8/16 g (при включении — ±2 g), g или м/с².
lab-p4-param-accel_unit-option-0 = отсчёты, диапазон ±2 g (при включении)
lab-p4-param-accel_unit-option-1 = отсчёты, диапазон ±4 g
lab-p4-param-accel_unit-option-2 = отсчёты, диапазон ±8 g
lab-p4-param-accel_unit-option-3 = отсчёты, диапазон ±16 g
lab-p4-param-accel_unit-option-4 = g
lab-p4-param-accel_unit-option-5 = м/с²
lab-p4-param-gyro_unit = столбцы гироскопа
lab-p4-param-gyro_unit-help = Столбцы гироскопа: отсчёты диапазона ±250/500/1000/2000 °/с (при включении — ±250 °/с), °/с или рад/с.
lab-p4-param-gyro_unit-option-0 = отсчёты, диапазон ±250 °/с (при включении)
lab-p4-param-gyro_unit-option-1 = отсчёты, диапазон ±500 °/с
lab-p4-param-gyro_unit-option-2 = отсчёты, диапазон ±1000 °/с
lab-p4-param-gyro_unit-option-3 = отсчёты, диапазон ±2000 °/с
lab-p4-param-gyro_unit-option-4 = °/с
lab-p4-param-gyro_unit-option-5 = рад/с
lab-p4-param-time_unit = столбец времени
lab-p4-param-time_unit-help = Столбец времени: секунды или миллисекунды (millis() в Arduino).
lab-p4-param-time_unit-option-0 = с
lab-p4-param-time_unit-option-1 = мс (millis() в Arduino)
lab-p2-accuracy-title = Точность за последние 60 с рядом с таблицей 3 статьи
lab-p5-diagram-0 = Собственные числа линеаризованного шага
lab-p2-scene-field = поле
lab-p2-scene-nadir = надир
lab-p2-scene-sun = Солнце
