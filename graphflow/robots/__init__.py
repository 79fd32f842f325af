"""``graphflow robot add``: converted URDF/MJCF robots made simulatable (drives, home pose, physics-only).

NVIDIA's converters (``urdf-usd-converter``, ``mujoco-usd-converter``) run as separate processes
(``converters``): their ``usd-exchange`` ships its own ``pxr``, which graphflow's ``usd-core`` would
overwrite. Everything after the conversion is graphflow's and uses usd-core only: the drive rule
(``gains``), the home pose (``home``), what the conversion loses (``dropped``), physics-only flattening
(``physics_only``), a suction tool (``suction``), tied together by ``post_process``.
"""
