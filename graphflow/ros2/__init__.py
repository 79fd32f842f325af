"""ROS 2 graphs without ROS: a per-world topic bus, scripted topics, MCAP recording.

``bus`` holds the world service every ROS 2 bridge node talks to;
``messages`` checks messages against the standard ROS 2 definitions (rosbags'
type store); ``timeline`` reads scripted topics (``graphflow run --topics``); ``run`` wires both into a run;
``mcap_recording`` writes published messages to MCAP with CDR encoding.
"""
