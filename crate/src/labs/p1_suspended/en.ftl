# Lab p1: English words for what its code writes as a code (a log column's
# unit choice the CLI takes as written, `--rate-unit deg_s`). Every id here is in ru.ftl too.

lab-p1-param-rate_unit = rate column
lab-p1-param-rate_unit-option-0 = °/s
lab-p1-param-rate_unit-option-1 = m°/s (the paper's lab software)
lab-p1-param-rate_unit-option-2 = rad/s
lab-p1-param-time_unit = time column
lab-p1-param-time_unit-option-0 = s
lab-p1-param-time_unit-option-1 = ms
