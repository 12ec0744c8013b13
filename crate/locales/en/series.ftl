# The words series labels are made of (crate/src/i18n/series.rs): who records a series, and
# the measures every estimator's covariance gives. They must read exactly as the core writes
# its English labels (crate/src/sim/catalogue.rs); a test composes every series of every lab
# from these and compares.

series-time = time t
owner-truth = Truth
owner-sensors = Sensors
series-variance = variance of the { $state }
series-covariance = covariance of the { $a } and the { $b }
series-nees = attitude NEES eᵀP⁻¹e
series-health = health (0 = ok)

## A covariance state, as the variance and the covariance name it
state-attitude-axis = attitude about { $axis }
state-rate-axis = rate about { $axis }
state-gyro-bias-axis = gyro bias about { $axis }
state-mag-bias-axis = magnetometer bias along { $axis }
state-mag-turn-axis = magnetometer bias: turn of the field about { $axis }
state-angle = angle
state-rate = rate
