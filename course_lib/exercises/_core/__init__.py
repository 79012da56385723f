"""The exercise machinery, one module per topic; import it from
:mod:`course_lib.exercises.core`."""
