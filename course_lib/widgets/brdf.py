r"""BRDF explorer: the reflected lobe of Lambert, Phong and Blinn-Phong in the plane of
incidence, and whether the model conserves energy.

The light arrives from the left at the angle :math:`\theta_i` from the normal, :math:`l =
(-\sin\theta_i, 0, \cos\theta_i)`; the curve is the polar plot, over the viewing directions
:math:`v = (\sin t, 0, \cos t)` of the plane of incidence, of

.. math:: g(v) = f_r(l, v)\cos\theta_v,

the BRDF weighted by the cosine of the outgoing angle: the reflected power per unit solid angle
and unit irradiance, whose integral over the hemisphere is the directional-hemispherical
reflectance :math:`\rho(l)`. (The curve is scaled to the plot: its peak value is printed.)
The BRDF is :math:`k_d/\pi` plus, for Phong and Blinn-Phong, the lobe of
:func:`course_lib.shading.phong_brdf` (``normalized`` or ``modified``) or
:func:`course_lib.shading.blinn_phong_brdf` (``exact`` or ``none``).

The info panel prints :math:`\rho(l) = k_d + k_s\,\rho_{lobe}(l)`: the lobe's reflectance
:math:`\rho_{lobe}` for :math:`k_s = 1` is computed by quadrature
(:func:`course_lib.shading.hemispherical_reflectance`) once per (model, incidence, exponent,
normalisation) and cached, since it scales linearly with :math:`k_s`. A value above 1 (a
normalised model with :math:`k_d + k_s > 1`, or an unnormalised lobe with a small exponent) is
shown in red: the surface would reflect more energy than it receives.
"""
from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from .. import draw
from .._validate import as_choice
from ..shading import brdf
from . import _style
from ._base import Explorer, bind, checkbox, panel, slider

__all__ = ["MODELS", "BRDFExplorer", "State", "lobe_reflectance", "scene"]

MODELS = ("Lambert", "Phong", "Blinn-Phong")
ANGLES = np.radians(np.linspace(-90.0, 90.0, 361))     # viewing directions in the plane
ORDER = 24                                              # quadrature points per piece and axis
_Z = np.array([0.0, 0.0, 1.0])


@dataclass
class State:
    """The model, the light's angle of incidence, the exponent and the coefficients.

    Examples
    --------
    >>> State().model, State().normalized
    ('Phong', True)
    """

    model: str = "Phong"
    theta_i_deg: float = 40.0
    shininess: float = 20.0
    kd: float = 0.4
    ks: float = 0.5
    normalized: bool = True


def _light(theta_i_deg):
    t = np.radians(theta_i_deg)
    return np.array([-np.sin(t), 0.0, np.cos(t)])


def _lobe(model, l, v, shininess, normalized):
    """The specular lobe for k_s = 1 (0 for Lambert), at the directions v (m, 3)."""
    if model == "Phong":
        return brdf.phong_brdf(l, v, _Z, 1.0, shininess, "normalized" if normalized else
                               "modified", below="zero")
    if model == "Blinn-Phong":
        return brdf.blinn_phong_brdf(l, v, _Z, 1.0, shininess, "exact" if normalized else
                                     "none", below="zero")
    return np.zeros(len(v))


@lru_cache(maxsize=4096)
def lobe_reflectance(model, theta_i_deg, shininess, normalized):
    r"""The reflectance :math:`\rho_{lobe}(l)` of the specular lobe with :math:`k_s = 1`
    (cached).

    Examples
    --------
    >>> round(lobe_reflectance("Phong", 0.0, 20.0, True), 6)
    1.0
    >>> round(lobe_reflectance("Phong", 0.0, 20.0, False), 6)     # 2 pi / 22
    0.285599
    """
    as_choice(model, "model", MODELS)
    if model == "Lambert":
        return 0.0
    l = _light(theta_i_deg)
    return float(brdf.hemispherical_reflectance(
        lambda a, v, n: _lobe(model, a, v, shininess, normalized), l, _Z, shininess,
        order=ORDER))


def scene(state):
    """Pure part: the lobe curve, the incident and mirror directions, the reflectance and text.

    Examples
    --------
    >>> s = scene(State(model="Lambert", kd=0.5, theta_i_deg=30))
    >>> round(s["reflectance"], 12), round(float(s["g"].max() * np.pi), 12)
    (0.5, 0.5)
    >>> scene(State(kd=0.7, ks=0.5))["conserving"]
    False
    """
    model = as_choice(state.model, "model", MODELS)
    theta = float(state.theta_i_deg)
    if not 0 <= theta <= 89.5:
        raise ValueError(f"theta_i_deg must be in [0, 89.5], got {theta:g}")
    n_exp = float(state.shininess)
    kd, ks = float(state.kd), float(state.ks)
    l = _light(theta)
    v = np.stack([np.sin(ANGLES), np.zeros_like(ANGLES), np.cos(ANGLES)], axis=-1)
    diffuse = brdf.lambert_brdf(l, v, _Z, kd, below="zero")
    ks_used = 0.0 if model == "Lambert" else ks
    lobe = ks_used * _lobe(model, l, v, n_exp, state.normalized)
    f = diffuse + lobe
    g = f * np.cos(ANGLES)
    peak = float(g.max())
    scale = 1.0 / peak if peak > 0 else 1.0
    curve = np.stack([g * scale * np.sin(ANGLES), g * scale * np.cos(ANGLES)], axis=-1)
    rho_lobe = lobe_reflectance(model, theta, n_exp, bool(state.normalized))
    rho = kd + ks_used * rho_lobe
    conserving = rho <= 1 + 1e-9
    mirror = np.array([-l[0], l[2]])
    form = {"Phong": ("k_s (n+2)/(2π) cos^n α" if state.normalized else "k_s cos^n α"),
            "Blinn-Phong": ("C(n) k_s cos^n θ_h, exact C" if state.normalized else
                            "k_s cos^n θ_h"),
            "Lambert": ""}[model]
    brdf_text = "k_d/π" + (f" + {form}" if form else "")
    colour = "#2e7d32" if conserving else "#c62828"
    verdict = ("≤ 1: energy is conserved" if conserving else
               "> 1: the surface reflects more energy than it receives")
    text = (f"<b>{model}</b>, f<sub>r</sub> = {brdf_text}, θ<sub>i</sub> = {theta:g}°"
            + ("" if model == "Lambert" else f", n = {n_exp:g}") + ". "
            f"Curve: f<sub>r</sub>(l, v) cos θ<sub>v</sub> in the plane of incidence, peak "
            f"{peak:.3g} sr⁻¹.<br>Reflectance ρ(l) = k<sub>d</sub>"
            + ("" if model == "Lambert" else
               f" + k<sub>s</sub>·{rho_lobe:.4f}") +
            f" = <b style='color:{colour}'>{rho:.4f}</b> {verdict}.")
    if model != "Lambert" and state.normalized and kd + ks > 1:
        text += (f" <span style='color:#c62828'>k<sub>d</sub> + k<sub>s</sub> = {kd + ks:.2f} "
                 "&gt; 1: a normalised model then breaks energy conservation (at normal "
                 "incidence ρ = k<sub>d</sub> + k<sub>s</sub>).</span>")
    if model != "Lambert" and not state.normalized:
        text += (" Unnormalised: the lobe's reflectance at normal incidence is "
                 + ("2π/(n+2)" if model == "Phong" else "8π(n + 2<sup>−n/2</sup>)/((n+2)(n+4))")
                 + " per unit k<sub>s</sub>, above 1 for small n, tiny for large n.")
    return {"v_angles": ANGLES, "f": f, "g": g, "curve": curve, "peak": peak,
            "incident": np.array([l[0], l[2]]), "mirror": mirror, "reflectance": rho,
            "lobe_reflectance": rho_lobe, "conserving": bool(conserving), "text": text}


class BRDFExplorer(Explorer):
    """Model toggle, incidence and exponent sliders, k_d / k_s, normalised or not: the lobe and
    the reflectance.

    In a notebook, after ``%matplotlib widget``, end a cell with ``BRDFExplorer()``.

    Examples
    --------
    >>> explorer = BRDFExplorer()
    >>> explorer.theta.value = 60.0
    >>> [round(float(x), 6) for x in explorer.incident_line.get_xdata()]
    [0.0, -0.866025]
    """

    summary = ("BRDF explorer (interactive): the reflected lobe f_r cos(theta_v) of Lambert, "
               "Phong and Blinn-Phong in the plane of incidence, normalised or not, and the "
               "directional-hemispherical reflectance (energy conserved when <= 1).")

    def __init__(self, state=None):
        import ipywidgets as w

        self.state = state or State()
        s = scene(self.state)
        self.fig = draw.figure(figsize=(5.2, 3.0))
        ax = self.fig.add_axes((0.05, 0.08, 0.9, 0.8))
        ax.set(xlim=(-1.15, 1.15), ylim=(-0.12, 1.12), aspect="equal")
        ax.axis("off")
        ax.plot([-1.15, 1.15], [0, 0], color="0.3", lw=1.5)
        ax.fill_between([-1.15, 1.15], [-0.12, -0.12], [0, 0], color="0.88")
        ax.plot([0, 0], [0, 1.05], color="0.6", lw=0.8, ls=":")
        ax.text(0.02, 1.05, "n", color="0.4")
        t = np.linspace(0, np.pi, 100)
        ax.plot(np.cos(t), np.sin(t), color="0.85", lw=0.8)
        (self.incident_line,) = ax.plot([], [], color="#f9a825", lw=2, label="towards light l")
        (self.mirror_line,) = ax.plot([], [], color="0.45", lw=1, ls="--",
                                      label="mirror direction R")
        (self.lobe_line,) = ax.plot([], [], color="C0", lw=2, label="f_r cos θ_v (scaled)")
        self.title = ax.set_title("", fontsize=9)
        _style.legend(ax, loc="upper right", fontsize=7, handlelength=1.5)
        _style.style_figure(self.fig)
        self.blitter = draw.Blitter(self.fig, [self.incident_line, self.mirror_line,
                                               self.lobe_line, self.title])
        self.model = w.ToggleButtons(options=MODELS, value=self.state.model,
                                     style={"button_width": _style.button_width(*MODELS)})
        self.theta = slider("θ_i °", self.state.theta_i_deg, 0, 89, 1)
        self.shininess = slider("shininess n", self.state.shininess, 1, 500, 1)
        self.kd = slider("k_d", self.state.kd, 0, 1, 0.01)
        self.ks = slider("k_s", self.state.ks, 0, 1, 0.01)
        self.normalized = checkbox("normalised", self.state.normalized)
        bind(self.state, {"model": self.model, "theta_i_deg": self.theta,
                          "shininess": self.shininess, "kd": self.kd, "ks": self.ks,
                          "normalized": self.normalized}, self.update)
        self.info = panel(width="640px")
        self.widget = w.VBox([self.fig.canvas, self.model,
                              w.HBox([w.VBox([self.theta, self.shininess]),
                                      w.VBox([self.kd, self.ks, self.normalized])],
                                     layout=w.Layout(flex_flow="row wrap")),
                              self.info])
        self._draw(s)

    def update(self):
        """Recompute the scene (the lobe reflectance is cached) and redraw the moving lines."""
        self._draw(scene(self.state))
        self.blitter.update()

    def _draw(self, s):
        self.incident_line.set_data([0, s["incident"][0]], [0, s["incident"][1]])
        self.mirror_line.set_data([0, s["mirror"][0]], [0, s["mirror"][1]])
        self.lobe_line.set_data(s["curve"][:, 0], s["curve"][:, 1])
        colour = "#2e7d32" if s["conserving"] else "#c62828"
        self.title.set_text(f"ρ(l) = {s['reflectance']:.3f}   (peak {s['peak']:.3g} sr⁻¹)")
        self.title.set_color(colour)
        self.info.value = s["text"]
