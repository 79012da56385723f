"""course_lib: the algorithms of the graphics and visualization course, with drawing and widgets.

The algorithm modules (``transforms``, ``quaternions``, ...) use numpy only and are safe to import
anywhere; ``course_lib.draw`` and ``course_lib.widgets`` add matplotlib, ipywidgets and pyvista on
top of them.
"""
__version__ = "0.1.0"
