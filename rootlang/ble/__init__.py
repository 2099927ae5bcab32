"""Real robots over Bluetooth Low Energy: scanning, picking a robot, and the bleak transport.

bleak is imported only inside the functions that talk to radios, so ``rootlang check`` and the
simulator never pay for it. ``rootlang.ble.virtual`` (optional extra) serves a simulated robot
over bumble and lets bleak run over bumble for tests.
"""
