"""The interactive explorers, one module each (ipywidgets + ipympl on top of course_lib.draw).

Chapter 3: :mod:`quaternion` (QuaternionExplorer), :mod:`slerp` (SlerpExplorer),
:mod:`gimbal` (GimbalExplorer), :mod:`composer` (ComposerExplorer); every other chapter's
explorers likewise, one module each.

Importing the package makes the running kernel (if any) handle widget messages on its main
thread (:func:`course_lib.widgets._base.handle_comms_on_main_thread`): JupyterLab's default
sends them to subshell threads, where matplotlib and VTK must not draw.
"""
from ._base import handle_comms_on_main_thread

handle_comms_on_main_thread()
