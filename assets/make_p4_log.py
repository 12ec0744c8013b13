"""Writes assets/p4-arduino-mpu6050.csv: a synthetic Arduino serial log of an MPU-6050 on
paper 4's lever (100 Hz, raw counts at the power-on ranges ±2 g and ±250 deg/s, millis()).

The lever follows a second-order response (5 rad/s, damping 0.8) to a 0/20 deg square wave of
period 8 s; the IMU sits 0.1 m from the pivot, so the accelerometer feels r*theta'' and
r*theta'^2; noise is the datasheet's (400 ug/sqrt(Hz), 0.005 deg/s/sqrt(Hz) through a 44-Hz
DLPF) with a 0.5 deg/s zero-rate offset on gx. Run: python3 assets/make_p4_log.py
"""
import math
import random

random.seed(4)
lines = ["Initializing I2C devices...", "Testing device connections...",
         "MPU6050 connection successful", "ms,ax,ay,az,gx,gy,gz"]
dt, theta, omega, wn, zeta, r = 0.01, 0.0, 0.0, 5.0, 0.8, 0.1
sa = 400e-6 * math.sqrt(1.57 * 44)
sg = 0.005 * math.sqrt(1.57 * 44)
for k in range(1000):
    t = k * dt
    sp = math.radians(20.0) if (t % 8.0) >= 4.0 else 0.0
    acc = wn * wn * (sp - theta) - 2 * zeta * wn * omega
    omega += acc * dt
    theta += omega * dt
    fy = (9.80665 * math.sin(theta) - r * omega * omega) / 9.80665
    fz = (9.80665 * math.cos(theta) + r * acc) / 9.80665
    ax = round(random.gauss(0, sa) * 16384)
    ay = round((fy + random.gauss(0, sa)) * 16384)
    az = round((fz + random.gauss(0, sa)) * 16384)
    gx = round((math.degrees(omega) + 0.5 + random.gauss(0, sg)) * 131.072)
    gy = round(random.gauss(0, sg) * 131.072)
    gz = round((-0.3 + random.gauss(0, sg)) * 131.072)
    lines.append(f"{int(round(t * 1000))},{ax},{ay},{az},{gx},{gy},{gz}")
with open("assets/p4-arduino-mpu6050.csv", "w") as f:
    f.write("\n".join(lines) + "\n")
