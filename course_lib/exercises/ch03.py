r"""Chapter 3 exercises: transformations (2D and 3D) and quaternions, exam style.

Each class is one kind of exam question. Its ``seed`` draws numbers that are easy to work with by
hand: angles that are multiples of 15 or 30 degrees, small whole translations and points, axes
with whole lengths such as :math:`(1, 2, 2)` (length 3) or :math:`(0, 3, 4)` (length 5), and
quaternions with rational components. The newer topics: a normal under a shear (the inverse
transpose), coordinates in another frame, scaling about a point, homogeneous matrices whose
:math:`w` is not 1, and mirroring about a plane. The question's numbers are attributes of the exercise
object (``ex.theta``, ``ex.d``, ...), so that a worked solution can read them for any seed.

The expected answers are computed with :mod:`course_lib.transforms` and
:mod:`course_lib.quaternions`. Every exercise anticipates the typical mistakes of its topic (the
product in the wrong order, a transposed matrix, the full angle in a quaternion, ...) and names
them in the feedback. The numbers are drawn again until every anticipated mistake gives an answer
that differs clearly from the right one and from the other mistakes, so a diagnosis is never
ambiguous (:class:`~course_lib.exercises.core.DrawnExercise`).

Conventions: column vectors (:math:`p' = M p`), angles positive counter-clockwise, quaternions
scalar first :math:`(s, x, y, z)`.

The exercises live in :mod:`course_lib.exercises._ch03`, one module per topic (what
the topics share is in its ``__init__``); import them from here.
"""
from ._ch03.composition import (ComposeMatrix2D, InverseOfComposite, MirrorAboutLine,
                                RotateAboutPoint)
from ._ch03.shears import ShearImage, ShearInverse, ShearedBoxVolume
from ._ch03.axis_rotation import RotationAboutArbitraryAxis
from ._ch03.unit_quaternions import (ComposeRotationsWithQuaternions, QuaternionFromAxisAngle,
                                     QuaternionProduct, RotatePointWithQuaternion, SlerpMidpoint)
from ._ch03.rotation_matrices import AxisAngleOfMatrix, MatrixToQuaternion, QuaternionToMatrix

from ._ch03.frames import (FrameCoordinates, HomogeneousRotationAngle, MirrorAboutPlane,
                           NormalUnderShear, ScaleAboutPoint)

__all__ = [
    "EXERCISES",
    "AxisAngleOfMatrix",
    "ComposeMatrix2D",
    "ComposeRotationsWithQuaternions",
    "FrameCoordinates",
    "HomogeneousRotationAngle",
    "InverseOfComposite",
    "MatrixToQuaternion",
    "MirrorAboutLine",
    "MirrorAboutPlane",
    "NormalUnderShear",
    "QuaternionFromAxisAngle",
    "QuaternionProduct",
    "QuaternionToMatrix",
    "RotateAboutPoint",
    "RotatePointWithQuaternion",
    "RotationAboutArbitraryAxis",
    "ScaleAboutPoint",
    "ShearImage",
    "ShearInverse",
    "ShearedBoxVolume",
    "SlerpMidpoint",
]

#: The exercises of chapter 3, in the order of the solutions notebook.
EXERCISES = (
    ComposeMatrix2D,
    RotateAboutPoint,
    InverseOfComposite,
    MirrorAboutLine,
    ShearInverse,
    ShearImage,
    ShearedBoxVolume,
    RotationAboutArbitraryAxis,
    QuaternionFromAxisAngle,
    QuaternionProduct,
    RotatePointWithQuaternion,
    QuaternionToMatrix,
    MatrixToQuaternion,
    AxisAngleOfMatrix,
    ComposeRotationsWithQuaternions,
    SlerpMidpoint,
    NormalUnderShear,
    FrameCoordinates,
    ScaleAboutPoint,
    HomogeneousRotationAngle,
    MirrorAboutPlane,
)
