"""Devices a graph reads: the keyboard, the gamepad, and the scripted timelines they share."""
