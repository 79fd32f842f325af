"""Planar angle helpers shared by the wheeled-robot path nodes (QuinticPathPlanner, StanleyControlPID)."""
import math


def normalize_angle(angle: float) -> float:
    """*angle* wrapped into [-pi, pi] (pi stays pi, as Isaac's controllers wrap it)."""
    if not math.isfinite(angle):
        raise ValueError(f"angle {angle} is not finite")
    wrapped = (angle + math.pi) % (2.0 * math.pi) - math.pi
    return math.pi if wrapped == -math.pi and angle > 0.0 else wrapped


def yaw_of(quaternion) -> float:
    """The yaw (rad, [-pi, pi]) of an (x, y, z, w) quaternion; 0 for a zero or malformed one, as Isaac."""
    if len(quaternion) != 4 or not all(math.isfinite(c) for c in quaternion) or not any(quaternion):
        return 0.0
    x, y, z, w = quaternion
    return normalize_angle(math.atan2(2.0 * (w * z + x * y), 1.0 - 2.0 * (y * y + z * z)))
