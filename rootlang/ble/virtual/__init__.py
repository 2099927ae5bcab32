"""A virtual robot on a real BLE stack (bumble), and a bleak backend over bumble's central role.

Needs the optional extra ``virtual`` (``pip install 'rootlang[virtual]'``). Nothing else in
rootlang imports this package unless asked to: bumble is large and optional.
"""
