"""Chapter 3: quaternion conversions against scipy's Rotation, and the chapter's widgets."""
import numpy as np

from benchmarks import operation_row, widget_row


def operations(quick=False):
    from scipy.spatial.transform import Rotation, Slerp

    from course_lib import quaternions

    n = 2_000 if quick else 100_000
    repeat = 3 if quick else 25
    rng = np.random.default_rng(2026)
    q = Rotation.random(n, random_state=rng).as_quat(scalar_first=True)
    m = quaternions.to_matrix(q)
    q2 = Rotation.random(n, random_state=rng).as_quat(scalar_first=True)
    points = rng.normal(size=(n, 3))
    t = np.linspace(0, 1, n)
    r, r2 = Rotation.from_quat(q, scalar_first=True), Rotation.from_quat(q2, scalar_first=True)
    slerp = Slerp([0, 1], Rotation.from_quat(q[:2], scalar_first=True))
    sci = "scipy Rotation"
    rows = [
        operation_row("quaternion -> matrix", n, lambda: quaternions.to_matrix(q),
                      lambda: Rotation.from_quat(q, scalar_first=True).as_matrix(), sci, repeat),
        operation_row("matrix -> quaternion", n, lambda: quaternions.from_matrix(m),
                      lambda: Rotation.from_matrix(m).as_quat(scalar_first=True), sci, repeat),
        operation_row("quaternion product", n, lambda: quaternions.multiply(q, q2),
                      lambda: (r * r2).as_quat(scalar_first=True), sci, repeat),
        operation_row("rotate points (one q each)", n, lambda: quaternions.rotate(q, points),
                      lambda: r.apply(points), sci, repeat),
        operation_row("slerp (one pair, many t)", n, lambda: quaternions.slerp(q[0], q[1], t),
                      lambda: slerp(t).as_quat(scalar_first=True), "scipy Slerp", repeat),
    ]
    for topic in _topics():
        rows += topic.operations(quick)
    return rows


def _topics():
    from benchmarks import ch03_frames

    return (ch03_frames,)


def widgets(quick=False):
    import matplotlib

    matplotlib.use("module://ipympl.backend_nbagg")
    import matplotlib.pyplot as plt

    from course_lib.widgets import composer, gimbal, quaternion, slerp

    repeat = 5 if quick else 60
    rows = []

    def measure(name, explorer, move):
        explorer.fig.canvas.draw()                 # the first full draw, as on display
        rows.append(widget_row(name, move, explorer.fig.canvas.draw, repeat))
        plt.close(explorer.fig)

    ex = quaternion.QuaternionExplorer()
    measure("quaternion explorer (angle slider)", ex,
            lambda i: setattr(ex.angle, "value", -180 + (7 * i) % 360))
    ex = slerp.SlerpExplorer()
    measure("slerp explorer (t slider)", ex, lambda i: setattr(ex.t, "value", (i % 50) / 50))
    ex = gimbal.GimbalExplorer()
    measure("gimbal-lock explorer (pitch slider)", ex,
            lambda i: setattr(ex.pitch, "value", -90 + (7 * i) % 180))
    ex = composer.ComposerExplorer()
    measure("transformation composer (rotate slider)", ex,
            lambda i: setattr(ex.rows[1].sliders[0], "value", -180 + (7 * i) % 360))
    for topic in _topics():
        rows += topic.widgets(quick)
    return rows
