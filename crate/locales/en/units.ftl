# Words for what a lab's code writes as a code: the unit choices of a recorded log's columns
# (the CLI takes the codes as written: `--rate-unit deg_s`), and the columns they belong to.
# Every id here is also in ../ru/units.ftl.

lab-p1-param-rate_unit = rate column
lab-p1-param-rate_unit-option-0 = °/s
lab-p1-param-rate_unit-option-1 = m°/s (the paper's lab software)
lab-p1-param-rate_unit-option-2 = rad/s
lab-p1-param-time_unit = time column
lab-p1-param-time_unit-option-0 = s
lab-p1-param-time_unit-option-1 = ms
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
