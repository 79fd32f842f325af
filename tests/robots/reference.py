"""The fixture arm's mechanics by hand, in numpy: link frames, inertia about each joint axis, gravity torques.

Written from the fixture's numbers (tests/robots/converted.py), independently of graphflow's pose code."""
import math

import numpy as np

G = 9.81
# (mass, centre of mass in the link frame, diagonal inertia) of upper and lower; the fingers are point-like
UPPER = (2.0, np.array([0.0, 0.0, 0.15]), np.diag([0.02, 0.02, 0.001]))
LOWER = (1.0, np.array([0.0, 0.0, 0.1]), np.diag([0.01, 0.01, 0.001]))
FINGER = (0.25, np.zeros(3), np.diag([1e-4, 1e-4, 1e-4]))
SHOULDER = np.array([0.0, 0.0, 0.1])    # world, the shoulder's origin; the base does not move
Y = np.array([0.0, 1.0, 0.0])


def rot_y(angle):
    c, s = math.cos(angle), math.sin(angle)
    return np.array([[c, 0.0, s], [0.0, 1.0, 0.0], [-s, 0.0, c]])


def frames(shoulder, elbow, finger_a=0.0, finger_b=0.0):
    """World (rotation, origin) of upper, lower, finger_a, finger_b."""
    upper = (rot_y(shoulder), SHOULDER)
    lower_rotation = upper[0] @ rot_y(elbow)
    lower = (lower_rotation, SHOULDER + upper[0] @ np.array([0.0, 0.0, 0.3]))
    tip = lower[1] + lower_rotation @ np.array([0.0, 0.0, 0.2])
    x = lower_rotation @ np.array([1.0, 0.0, 0.0])
    return upper, lower, (lower_rotation, tip + finger_a * x), (lower_rotation, tip + finger_b * x)


def inertia_about(axis_point, bodies):
    """Sum over (body, frame) of m |r_perp|^2 + a^T R I R^T a about the Y axis through *axis_point*."""
    total = 0.0
    for (mass, centre, inertia), (rotation, origin) in bodies:
        r = origin + rotation @ centre - axis_point
        total += mass * (r @ r - (r @ Y) ** 2) + Y @ rotation @ inertia @ rotation.T @ Y
    return total


def carried(shoulder, elbow, fingers=(0.0, 0.0)):
    """(I shoulder, I elbow, m finger) at the pose: what the drive rule is made from."""
    upper, lower, a, b = frames(shoulder, elbow, *fingers)
    beyond_elbow = [(LOWER, lower), (FINGER, a), (FINGER, b)]
    return (inertia_about(SHOULDER, [(UPPER, upper)] + beyond_elbow), inertia_about(lower[1], beyond_elbow),
            FINGER[0])


def gravity_torques(shoulder, elbow, fingers=(0.0, 0.0)):
    """Gravity torque about +Y on the shoulder and the elbow (N m): sum of (c - p) x (m g) . Y."""
    upper, lower, a, b = frames(shoulder, elbow, *fingers)
    weight = np.array([0.0, 0.0, -G])

    def torque(point, bodies):
        return sum(np.cross(origin + rotation @ centre - point, mass * weight) @ Y
                   for (mass, centre, _), (rotation, origin) in bodies)

    beyond_elbow = [(LOWER, lower), (FINGER, a), (FINGER, b)]
    return torque(SHOULDER, [(UPPER, upper)] + beyond_elbow), torque(lower[1], beyond_elbow)
