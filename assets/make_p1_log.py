"""Writes assets/p1-vg910d-counts.csv: a synthetic log of paper 1's VG-910D on the suspended
mock-up, as raw counts: unsigned 24-bit words in two's complement, 10 Hz for 600 s, the time
in milliseconds (the paper's lab software logs ms).

The body twists as the lab's default damped torsion pendulum (steel string 0.35 mm, 1 m,
I = 0.48 kg m^2: T = 400.98 s; damping ratio 0.05) from 360 deg at rest. The gyro adds white
noise of 0.04 deg/s (the paper's Sigma) and reads 1 258 counts at rest. Its scale is the
nominal one, +-200 deg/s over 2^23 counts (the paper gives no coefficients). To replay it:
rate unit mdeg_s, time unit ms, raw counts 24-bit words, scale 0.0238418579 (m deg/s per
count), zero 1258. Run: python3 assets/make_p1_log.py
"""
import math
import random

random.seed(1)
T, ZETA, PHI0_DEG = 400.98, 0.05, 360.0
SCALE_MDEG_S = 200e3 / 2**23
ZERO_COUNTS = 1258
W = 2 * math.pi / T
WD = W * math.sqrt(1 - ZETA**2)


def rate_deg_s(t):
    """The derivative of phi(t) = phi0 e^(-zeta W t) (cos WD t + zeta W / WD sin WD t)."""
    return -PHI0_DEG * W * W / WD * math.exp(-ZETA * W * t) * math.sin(WD * t)


lines = [
    "# VG-910D on the suspended mock-up: raw 24-bit words at 10 Hz (synthetic; see",
    "# assets/make_p1_log.py). Calibration: 0.0238418579 m deg/s per count, zero 1258.",
    "time_ms,gyro_word",
]
for k in range(6001):
    t = k * 0.1
    rate = rate_deg_s(t) + random.gauss(0.0, 0.04)
    count = round(rate * 1e3 / SCALE_MDEG_S) + ZERO_COUNTS
    lines.append(f"{k * 100},{count % 2**24}")
with open("assets/p1-vg910d-counts.csv", "w") as f:
    f.write("\n".join(lines) + "\n")
