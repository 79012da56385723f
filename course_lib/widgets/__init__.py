"""The interactive explorers, one module each (ipywidgets + ipympl on top of course_lib.draw).

Chapter 3: :mod:`quaternion` (QuaternionExplorer), :mod:`slerp` (SlerpExplorer),
:mod:`gimbal` (GimbalExplorer), :mod:`composer` (ComposerExplorer).
"""
