"""The shared input checks of course_lib/_validate.py: what passes, and what each rejects.

Every rejection must name the argument and say what was expected (the words the modules' own
tests match on). The older helpers (as_array, as_vector, ...) are covered by their doctests and
by every module's bad-input tests; these tests cover the counts, positive numbers, choices,
meshes, colours and random generators that each module used to check on its own.
"""
import numpy as np
import pytest

from course_lib import _validate as V


# ---------------------------------------------------------------------------------------------
# as_whole
# ---------------------------------------------------------------------------------------------

@pytest.mark.parametrize("value, expected", [(3, 3), (3.0, 3), (np.int64(4), 4),
                                             (np.float64(2.0), 2), (np.array(5), 5), (1, 1)])
def test_as_whole_passes_whole_numbers_as_int(value, expected):
    out = V.as_whole(value, "n", 1)
    assert out == expected and type(out) is int


@pytest.mark.parametrize("value, error, pattern", [
    (True, TypeError, r"^width must be a whole number, got a bool$"),
    (np.bool_(False), TypeError, r"^width must be a whole number, got a bool$"),
    (2.5, ValueError, r"^width must be a whole number >= 1, got 2.5$"),
    ("4", TypeError, r"^width must be a number, got a str$"),
    (None, TypeError, r"^width must be a number, got None$"),
    (np.nan, ValueError, r"^width must be finite"),
    (np.inf, ValueError, r"^width must be finite"),
    (0, ValueError, r"^width must be a whole number >= 1, got 0$"),
    (-3, ValueError, r"^width must be a whole number >= 1, got -3$"),
    ([4, 4], ValueError, r"^width must be a single number, got shape \(2,\)$"),
])
def test_as_whole_rejects_with_the_argument_named(value, error, pattern):
    with pytest.raises(error, match=pattern):
        V.as_whole(value, "width", 1)


def test_as_whole_at_least_words_the_failing_part():
    with pytest.raises(ValueError, match=r"^n must be at least 0, got -1$"):
        V.as_whole(-1, "n", at_least=True)
    with pytest.raises(ValueError, match=r"^times must be a whole number, got 1.5$"):
        V.as_whole(1.5, "times", at_least=True)
    assert V.as_whole(2.0, "n", 2, at_least=True) == 2


def test_as_whole_integer_type_rejects_every_float():
    assert V.as_whole(np.int32(7), "k", integer_type=True) == 7
    for bad in (3.0, 3.5, "3", np.array(3)):
        with pytest.raises(TypeError, match=r"^k must be a whole number"):
            V.as_whole(bad, "k", integer_type=True)
    with pytest.raises(TypeError, match="got a bool"):
        V.as_whole(True, "k", integer_type=True)
    with pytest.raises(ValueError, match=r"^k must be at least 2, got 1$"):
        V.as_whole(1, "k", 2, integer_type=True, at_least=True)


def test_as_whole_default_minimum_is_zero():
    assert V.as_whole(0, "depth") == 0
    with pytest.raises(ValueError, match=">= 0"):
        V.as_whole(-1, "depth")


# ---------------------------------------------------------------------------------------------
# as_positive
# ---------------------------------------------------------------------------------------------

@pytest.mark.parametrize("value", [1, 0.25, np.float32(3.5), np.array(2.0), 1e-300])
def test_as_positive_passes_positive_numbers_as_float(value):
    out = V.as_positive(value, "radius")
    assert type(out) is float and out == float(value)


@pytest.mark.parametrize("value, error, pattern", [
    (0, ValueError, r"^radius must be positive, got 0$"),
    (-1.5, ValueError, r"^radius must be positive, got -1.5$"),
    (np.nan, ValueError, r"^radius must be finite"),
    (np.inf, ValueError, r"^radius must be finite"),
    ("1", TypeError, r"^radius must be a number, got a str$"),
    ([1, 2], ValueError, r"^radius must be a single number, got shape \(2,\)$"),
])
def test_as_positive_rejects_with_the_argument_named(value, error, pattern):
    with pytest.raises(error, match=pattern):
        V.as_positive(value, "radius")


def test_as_positive_says_what_the_number_is():
    with pytest.raises(ValueError, match=r"^ior must be positive \(a refractive index\), got 0$"):
        V.as_positive(0, "ior", "a refractive index")


def test_as_positive_takes_a_bool_as_a_number_like_as_scalar():
    # as_scalar (on which as_positive builds) takes True as 1.0; only counts refuse bools
    assert V.as_positive(True, "x") == 1.0


# ---------------------------------------------------------------------------------------------
# as_choice
# ---------------------------------------------------------------------------------------------

def test_as_choice_passes_the_value_itself():
    options = ("euler", "rk2", "rk4")
    value = "rk2"
    assert V.as_choice(value, "method", options) is value
    assert V.as_choice(np.str_("rk4"), "method", options) == "rk4"
    assert V.as_choice(3, "dim", (2, 3)) == 3


@pytest.mark.parametrize("value, shown", [("rk3", "'rk3'"), ("RK4", "'RK4'"), (None, "None"),
                                          (4, "4"), (np.array([1, 2]), r"array\(\[1, 2\]\)"),
                                          (["rk4"], r"\['rk4'\]")])
def test_as_choice_lists_the_options_and_what_it_got(value, shown):
    with pytest.raises(ValueError,
                       match=rf"^method must be one of 'euler', 'rk2', 'rk4', got {shown}$"):
        V.as_choice(value, "method", ("euler", "rk2", "rk4"))


# ---------------------------------------------------------------------------------------------
# as_mesh
# ---------------------------------------------------------------------------------------------

TRI_V = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]]
TRI_F = [[0, 1, 2], [0, 1, 3]]


def test_as_mesh_returns_float_vertices_and_intp_faces():
    v, f = V.as_mesh(TRI_V, np.array(TRI_F, dtype=np.int32))
    assert v.dtype == float and v.shape == (4, 3)
    assert f.dtype == np.intp and f.tolist() == TRI_F


def test_as_mesh_takes_a_single_triangle():
    assert V.as_mesh(TRI_V, [1, 2, 3])[1].tolist() == [[1, 2, 3]]


@pytest.mark.parametrize("faces, pattern", [
    ([], r"^faces must contain at least one triangle, got an empty array$"),
    (np.zeros((0, 3), int), r"^faces must contain at least one triangle"),
    ([[0, 1, 4]], r"^faces refers to vertex 4 but there are 4 vertices$"),
    ([[0, -1, 2]], r"^faces refers to vertex -1 but there are 4 vertices$"),
    ([[0.0, 1.0, 2.0]], r"^faces must be an \(m, 3\) array of vertex indices .*type float64$"),
    ([[True, False, True]], r"^faces must be an \(m, 3\) array .*type bool$"),
    ([[0, 1, 2, 3]], r"^faces must be an \(m, 3\) array .*shape \(1, 4\)"),
    ([[0, 1, 2], [0, 1]], r"^faces must be an \(m, 3\) array of vertex indices"),
    ("abc", r"^faces must be an \(m, 3\) array"),
    (None, r"^faces must be an \(m, 3\) array"),
])
def test_as_mesh_rejects_bad_faces_naming_them(faces, pattern):
    with pytest.raises(ValueError, match=pattern):
        V.as_mesh(TRI_V, faces)


def test_as_mesh_names_the_faces_argument_as_the_caller_calls_it():
    with pytest.raises(ValueError, match=r"^triangles must contain at least one triangle"):
        V.as_mesh(TRI_V, [], "triangles")
    with pytest.raises(ValueError, match=r"^triangles refers to vertex 9"):
        V.as_mesh(TRI_V, [[0, 1, 9]], "triangles")


@pytest.mark.parametrize("vertices, error, pattern", [
    (np.zeros((0, 3)), ValueError, r"^vertices must be an \(n, 3\) array with n >= 1"),
    ([[0, 0], [1, 0], [0, 1]], ValueError, r"^vertices must have 3 coordinates"),
    ([0, 0, 0], ValueError, r"^vertices must be an \(n, 3\) array with n >= 1, got shape \(3,\)"),
    ([[0, 0, np.nan], [1, 0, 0], [0, 1, 0]], ValueError, r"^vertices must be finite"),
    ("abc", TypeError, r"^vertices must be numbers"),
])
def test_as_mesh_rejects_bad_vertices_naming_them(vertices, error, pattern):
    with pytest.raises(error, match=pattern):
        V.as_mesh(vertices, [[0, 1, 2]])


# ---------------------------------------------------------------------------------------------
# as_rgb
# ---------------------------------------------------------------------------------------------

def test_as_rgb_colours_and_greys():
    np.testing.assert_array_equal(V.as_rgb(0.25, "color"), [0.25, 0.25, 0.25])
    np.testing.assert_array_equal(V.as_rgb([1, 0, 0.5], "color"), [1, 0, 0.5])
    assert V.as_rgb(np.ones((4, 5, 3)), "colors").shape == (4, 5, 3)
    assert V.as_rgb(np.ones((4, 1)), "colors").shape == (4, 1)          # per-point greys
    np.testing.assert_array_equal(V.as_rgb([1 + 1e-12, -1e-12, 0], "rgb"), [1, 0, 0])


def test_as_rgb_intensities_are_unbounded_but_not_negative():
    np.testing.assert_array_equal(V.as_rgb([3, 2, 0], "intensity", maximum=None), [3, 2, 0])
    with pytest.raises(ValueError, match=r"^intensity must not be negative, got -1$"):
        V.as_rgb(-1, "intensity", maximum=None)
    with pytest.raises(ValueError, match=r"^ambient must not be negative, got -0.5 at index 2$"):
        V.as_rgb([0, 0, -0.5], "ambient", maximum=None)


@pytest.mark.parametrize("value, kwargs, error, pattern", [
    (1.5, {}, ValueError, r"^kd must lie in \[0, 1\], got 1.5$"),
    ([0.5, -0.1, 0], {}, ValueError, r"^kd must lie in \[0, 1\], got -0.1 at index 1$"),
    ([[0, 0, 0], [1, 2, 0]], {}, ValueError, r"^kd must lie in \[0, 1\], got 2 at index \(1, 1\)$"),
    ([0, np.nan, 0], {}, ValueError, r"^kd must be finite"),
    ("red", {}, TypeError, r"^kd must be numbers, got a str$"),
    (True, {}, None, None),
    ([1, 0], {}, ValueError, r"^kd must be a number \(grey\) or RGB triples with 3 components "
                             r"\(r, g, b\) in the last axis .*got shape \(2,\)$"),
    (0.5, {"grey": False}, ValueError, r"^kd must be RGB triples with 3 components"),
    (np.ones((2, 1)), {"grey": False}, ValueError, r"^kd must be RGB triples .*shape \(2, 1\)"),
    (np.ones((2, 3)), {"single": True}, ValueError,
     r"^kd must be a number \(grey\) or an RGB triple \(r, g, b\), got shape \(2, 3\)$"),
])
def test_as_rgb_rejects_with_the_argument_named(value, kwargs, error, pattern):
    if error is None:           # a bool is a number to as_array: True is the grey 1.0
        np.testing.assert_array_equal(V.as_rgb(value, "kd", **kwargs), [1, 1, 1])
        return
    with pytest.raises(error, match=pattern):
        V.as_rgb(value, "kd", **kwargs)


# ---------------------------------------------------------------------------------------------
# as_rng
# ---------------------------------------------------------------------------------------------

def test_as_rng_passes_a_generator_through_unchanged():
    g = np.random.default_rng(5)
    assert V.as_rng(g) is g
    assert V.as_rng(g, "rng") is g


def test_as_rng_seeds_reproducibly():
    a = V.as_rng(7).random(3)
    b = V.as_rng(np.int64(7)).random(3)
    np.testing.assert_array_equal(a, b)
    np.testing.assert_array_equal(a, np.random.default_rng(7).random(3))
    assert isinstance(V.as_rng(None), np.random.Generator)
    ss = np.random.SeedSequence(3)
    np.testing.assert_array_equal(V.as_rng(ss).random(2), np.random.default_rng(3).random(2))
    assert isinstance(V.as_rng(np.random.PCG64(1)), np.random.Generator)


@pytest.mark.parametrize("seed, error, pattern", [
    (True, TypeError, r"^seed must be None, a whole number >= 0 or a numpy.random.Generator, "
                      r"got a bool$"),
    (1.5, TypeError, r"^seed must be None, .* got a float$"),
    (np.nan, TypeError, r"^seed must be None, .* got a float$"),
    ("42", TypeError, r"^seed must be None, .* got a str$"),
    (-1, ValueError, r"^seed must be None, .* got -1$"),
    ([1, 2], TypeError, r"^seed must be None, .* got a list$"),
])
def test_as_rng_rejects_with_the_argument_named(seed, error, pattern):
    with pytest.raises(error, match=pattern):
        V.as_rng(seed)


def test_as_rng_names_the_argument():
    with pytest.raises(TypeError, match=r"^lattice_seed must be None"):
        V.as_rng("x", "lattice_seed")


# ---------------------------------------------------------------------------------------------
# each check is defined once
# ---------------------------------------------------------------------------------------------

def test_the_modules_keep_no_copies_of_the_shared_checks():
    """The copies this file's helpers replaced stay gone (a new one would drift again)."""
    import pathlib
    import re

    root = pathlib.Path(V.__file__).parent
    copies = re.compile(r"^def (_whole|_count|_pixels|_positive_int|_integer|_positive|"
                        r"_as_positive|_choice|_wrap_mode|_mesh|_rgb|_rng)\(", re.M)
    found = [f"{path.relative_to(root)}: def {m.group(1)}"
             for path in sorted(root.rglob("*.py")) if path.name != "_validate.py"
             for m in copies.finditer(path.read_text())]
    assert found == []
