"""Writes examples/noisy.csv: 101 noisy samples of y = sin(2 pi x) on [0, 1].

    /usr/bin/python3 examples/noisy_samples.py > examples/noisy.csv

x_i = i / 100 (i = 0..100), y_i = sin(2 pi x_i) + e_i with e_i ~ N(0, 0.1^2)
drawn by the Box-Muller transform from Python's random.Random(15).random(),
whose sequence for a given seed Python promises not to change between
versions; y is written with 6 decimals, so a last-bit difference of a libm
sine or logarithm does not change the file. The data of the README's
`fit examples/noisy.csv --degree 3 --smoothing gcv --function` (a smoothing
spline should come back close to the sine, within about the noise).
Only the standard library: no numpy needed.
"""

import math
import random


def main() -> None:
    rng = random.Random(15)
    print("# 101 samples of sin(2 pi x) + N(0, 0.1^2) noise, x = 0, 0.01, ..., 1: examples/noisy_samples.py")
    print("x,y")
    for i in range(101):
        x = i / 100
        u1, u2 = 1.0 - rng.random(), rng.random()  # u1 in (0, 1]: log(u1) is finite
        noise = math.sqrt(-2.0 * math.log(u1)) * math.cos(2.0 * math.pi * u2)
        print(f"{x:.2f},{math.sin(2.0 * math.pi * x) + 0.1 * noise:.6f}")


if __name__ == "__main__":
    main()
