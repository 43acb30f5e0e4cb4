#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""The two shear modes of a spinning square, in the block's frame.

A model of ndda's step for a block that spins at omega while its uniform
shear strain vibrates (doc/theory.md, "Finite rotation", point 4). The
two shear modes (xx - yy and xy) have one frequency ws; q holds their
amplitudes, nu their velocity relative to the block's frame, and the
quarter turn J of a displacement field acts on them as a quarter turn of
q. One step of ndda, seen from the block's frame, with the stiffness
force made consistent (the correction z of point 4a):

    dq = R^T (dt nu + dt^2/4 (a0 + a1)),  a1 = -ws^2 (q + dq),
    nu <- nu + dt/2 (a0 + a1) - c omega J dq,

where c = 1 is what the turn of the velocity gives and c = 2 adds the
Coriolis half of point 4b. The reference is the trapezoidal rule of the
rotating frame's equation q'' = -ws^2 q - 2 omega J q' + omega^2 q. The
script prints the largest energy (the rotating frame's invariant) over
the first, for c = 0, 1, 2, and the modes' amplitudes after 50 ms for
c = 2 against the trapezoidal rule.

Run with Debian's python3 (numpy): /usr/bin/python3 scripts/spin_shear_model.py
"""

import numpy as np

WS = 2 * np.pi / 0.23e-3  # the 0.5 m rock square's shear mode (rad/s)
J = np.array([[0.0, -1.0], [1.0, 0.0]])
I2 = np.eye(2)


def solve_linear(residual):
    """The root of a residual that is affine in a 2-vector."""
    r0 = residual(np.zeros(2))
    a = np.column_stack([residual(e) - r0 for e in I2])
    return np.linalg.solve(a, -r0)


def ndda_step(q, nu, a, omega, dt, c):
    theta = omega * dt
    rt = np.array([[np.cos(theta), np.sin(theta)],
                   [-np.sin(theta), np.cos(theta)]])
    dq = solve_linear(
        lambda x: x - rt @ (dt * nu + dt**2 / 4 * (a - WS**2 * (q + x))))
    a1 = -WS**2 * (q + dq)
    nu = nu + dt / 2 * (a + a1) - c * omega * J @ dq
    return q + dq, nu, a1


def trapezoidal_step(q, nu, a, omega, dt):
    def acceleration(q, v):
        return -WS**2 * q - 2 * omega * J @ v + omega**2 * q

    def residual(x):
        v1 = 2 * x / dt - nu
        return x - dt * nu - dt**2 / 4 * (a + acceleration(q + x, v1))

    dq = solve_linear(residual)
    v1 = 2 * dq / dt - nu
    return q + dq, v1, acceleration(q + dq, v1)


def energy(q, nu, omega):
    return 0.5 * nu @ nu + 0.5 * (WS**2 - omega**2) * q @ q


def run(step, omega, dt, end):
    q, nu = np.zeros(2), np.array([1e-4, 0.0])
    a = np.zeros(2)
    first, largest = energy(q, nu, omega), 0.0
    for _ in range(int(round(end / dt))):
        q, nu, a = step(q, nu, a)
        largest = max(largest, energy(q, nu, omega))
    return q, largest / first


def main():
    print("largest energy / first over 0.75 s, ndda's step with c times")
    print("the Coriolis term of the turn (c = 2: with point 4b)")
    print("| omega (rad/s) | dt (s) | c = 0 | c = 1 | c = 2 |")
    print("|---|---|---|---|---|")
    for omega in (5.0, 20.0):
        for dt in (2e-5, 1e-4, 1e-3):
            growth = [
                run(lambda q, nu, a: ndda_step(q, nu, a, omega, dt, c),
                    omega, dt, 0.75)[1] for c in (0, 1, 2)
            ]
            print(f"| {omega:g} | {dt:g} | " +
                  " | ".join(f"{g:.4g}" for g in growth) + " |")
    print()
    print("amplitudes after 50 ms at 20 rad/s (1e-9): ndda's step with")
    print("c = 2 against the trapezoidal rule of the rotating frame")
    print("| dt (s) | ndda, c = 2 | trapezoidal |")
    print("|---|---|---|")
    omega = 20.0
    for dt in (1e-4, 1e-5, 1e-6):
        q_ndda = run(lambda q, nu, a: ndda_step(q, nu, a, omega, dt, 2),
                     omega, dt, 0.05)[0]
        q_trap = run(lambda q, nu, a: trapezoidal_step(q, nu, a, omega, dt),
                     omega, dt, 0.05)[0]
        print(f"| {dt:g} | {q_ndda[0] / 1e-9:.4f}, {q_ndda[1] / 1e-9:.4f} "
              f"| {q_trap[0] / 1e-9:.4f}, {q_trap[1] / 1e-9:.4f} |")


if __name__ == "__main__":
    main()
