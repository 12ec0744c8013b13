# Lab p4: English words for what its code writes as a code (a log column's
# unit choice the CLI takes as written, `--rate-unit deg_s`). Every id here is in ru.ftl too.

lab-p4-param-accel_unit = accelerometer columns
lab-p4-param-accel_unit-option-0 = counts, ±2 g range (power-on)
lab-p4-param-accel_unit-option-1 = counts, ±4 g range
lab-p4-param-accel_unit-option-2 = counts, ±8 g range
lab-p4-param-accel_unit-option-3 = counts, ±16 g range
lab-p4-param-accel_unit-option-4 = g
lab-p4-param-accel_unit-option-5 = m/s²
lab-p4-param-gyro_unit = gyro columns
lab-p4-param-gyro_unit-option-0 = counts, ±250 °/s range (power-on)
lab-p4-param-gyro_unit-option-1 = counts, ±500 °/s range
lab-p4-param-gyro_unit-option-2 = counts, ±1000 °/s range
lab-p4-param-gyro_unit-option-3 = counts, ±2000 °/s range
lab-p4-param-gyro_unit-option-4 = °/s
lab-p4-param-gyro_unit-option-5 = rad/s
lab-p4-param-time_unit = time column
lab-p4-param-time_unit-option-0 = s
lab-p4-param-time_unit-option-1 = ms (Arduino millis())
