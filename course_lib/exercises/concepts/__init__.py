r"""Concept questions: multiple-choice and true/false questions on what to know by heart.

Besides the numeric exercises of each chapter, the exam asks for facts: which properties an
affine or a projective map keeps, which clipping algorithm clips what against what, which
properties a Bézier, B-spline or NURBS curve has, what the Euler characteristic of a closed
manifold mesh is, which Phong term depends on the viewer, and so on. Each
:class:`ConceptQuestion` asks one such fact, with an explanation for *every* option: why it is
right, or why it is wrong. :data:`QUESTIONS` holds them per chapter; :func:`questions` lists
them.

An answer is given as the option's index (counted from 0), its letter (``"a"`` or ``"B"``) or
its text; a true/false question also takes ``True``/``False`` and ``"true"``, ``"t"``,
``"false"``, ``"f"``. ``check`` never raises: an unanswered ``...`` or ``None`` gives the same
"not answered yet" as the exercises, an unreadable answer says which forms are accepted, and a
wrong option is answered with its explanation followed by the right option's.
"""
from .bank import QUESTIONS, questions
from .question import KINDS, TRUE_FALSE, ConceptQuestion

__all__ = ["KINDS", "QUESTIONS", "ConceptQuestion", "questions"]
