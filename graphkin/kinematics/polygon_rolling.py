"""Rolling contact in the velocity and acceleration polygons (Secs. 3.7 and 4.7).

No slip makes the two contact points one point for velocities (Eq. 3.13):
``V_C(i) = V_C(j)``; their accelerations differ by the rolling component
``A^r``, normal to the surfaces (Eq. 4.19).  So a contact carries the rates of
one link over to the other, whichever of the two is known first:

* the link that rolls (``link``) from the link it rolls on (``on``): its ω
  from one of its points and the contact, ``ω_i = V_CP/R_CP`` (a planet on
  its arm, a wheel on the ground);
* the link rolled on from the rolling link (a driven pinion turns its gear);
* a link with two points whose images are known, contact points included
  (a planet between a driven sun and a fixed ring: both its contact points
  are known, so its image is), by Mehmke's theorem; the pair is chosen with
  its points apart at the posture, so that two images at one place never
  make the link's image (Sec. 3.5).

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 3.5 (images), 3.7 (rolling
contact, Eq. 3.13), 4.7 (Eq. 4.19), 7.15 (planetary trains).
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from graphkin.construction import Construction, Role, Term, VectorEquation
from graphkin.construction import Mark as _Mark
from graphkin.kinematics.posture import PostureConstruction, _n
from graphkin.mechanisms.model import FRAME, Mechanism, Rolling
from graphkin.tolerance import DEFAULT_TOL

U = _Mark.UNKNOWN


def _vimg(label: str) -> str:
    return f"v({label})"


def _aimg(label: str) -> str:
    return f"a({label})"


class RollingRules:
    """The rolling steps of the polygons (a part of :class:`graphkin.kinematics.polygons._Poly`)."""

    mech: Mechanism
    pc: PostureConstruction
    v: Construction
    a: Construction
    vimg: dict[str, str]
    aimg: dict[str, str]
    omega: dict[str, str]
    alpha: dict[str, str]
    anchor: dict[str, str]

    def V(self, op: str, inputs: tuple[str, ...], out: str, **kw: Any) -> str:
        """Add a step to the velocity polygon (``_Poly.V``)."""
        raise NotImplementedError

    def A(self, op: str, inputs: tuple[str, ...], out: str, **kw: Any) -> str:
        """Add a step to the acceleration polygon (``_Poly.A``)."""
        raise NotImplementedError

    def coincident(self, k: str, x: str) -> tuple[str, str]:
        """Images of the point of link k at X (``_Poly.coincident``)."""
        raise NotImplementedError

    # ---- what is known ------------------------------------------------------------
    def rolling(self, key: str) -> Rolling:
        """The rolling contact with this key."""
        return next(r for r in self.mech.rolling if r.key == key)

    def ready(self, k: str) -> bool:
        """True when the images of every point of link k can be drawn (ω, α and an image)."""
        return k == FRAME or (k in self.omega and k in self.alpha and k in self.anchor
                              and self.anchor[k] in self.vimg and self.anchor[k] in self.aimg)

    def surface_ready(self, r: Rolling) -> bool:
        """True when the images of the link that carries the rolling surface can be drawn."""
        return self.ready(r.on)

    def apart(self, p: str, q: str) -> bool:
        """True when the points labelled p and q are apart at the file's posture."""
        vals = self.pc.values
        if p not in vals or q not in vals:
            return False
        a, b = np.asarray(vals[p], dtype=float), np.asarray(vals[q], dtype=float)
        if a.shape[-1] != 3 or b.shape[-1] != 3 or a[2] == 0 or b[2] == 0:
            return False
        d = math.hypot(a[0] / a[2] - b[0] / b[2], a[1] / a[2] - b[1] / b[2])
        return d > 1e3 * DEFAULT_TOL.length(self.mech.scale)

    def point_with_image(self, lid: str, away: str, acc: bool = True) -> str | None:
        """A named point of the link, with its images drawn, apart from the point ``away``."""
        for p in self.mech.links[lid].points:
            if p in self.vimg and (p in self.aimg or not acc) and self.apart(p, away):
                return p
        return None

    # ---- the contact point ------------------------------------------------------------
    def contact_images(self, r: Rolling) -> tuple[str, str]:
        """Images of the contact point C as a point of the roller (velocity, acceleration).

        No slip: ``V_C(link) = V_C(on)`` (Eq. 3.13); ``A_C(link) = A_C(on) + A^r``
        with A^r normal to the surfaces (Eq. 4.19).
        """
        cn = r.contact_name
        c = r.contact_label
        i, j = r.link, r.on
        vj, aj = self.coincident(j, c)
        al = _aimg(f"{c}@{i}")
        if al not in {o for st in self.a.steps for o in st.outputs}:
            ar = self.rolling_normal(r)
            self.A("translate", (aj, ar), al, role=Role.RESULT,
                   equation=VectorEquation((Term(f"A_{cn}{i}", U, U),),
                                           (Term(f"A_{cn}{j}"), Term(f"A_{cn}{i}/{j}^r")), case=1),
                   note=f"A_{cn}{i} = A_{cn}{j} + A_{cn}{i}/{j}^r (case 1).")
        return vj, al

    def rolling_normal(self, r: Rolling) -> str:
        """The rolling component ``A_Ci/j^r`` (Eq. 4.19), once."""
        cn = r.contact_name
        i, j = r.link, r.on
        lab = f"A_{cn}{i}/{j}^r"
        if lab in {o for st in self.a.steps for o in st.outputs}:
            return lab
        # ω of the roller is found in the velocity polygon (evaluated before this one)
        return self.A("rolling_normal", (r.contact_label, r.center, f"ω{i}", self.omega[j]), lab,
                      factor=r.factor,
                      note=f"Rolling contact: A_{cn}{i}/{j}^r = ρ ω²_rel (× R/(R ± ρ) on a "
                           "circle), normal to the surfaces, toward the center (Eq. 4.19).")

    # ---- the rolling link from the link it rolls on ---------------------------------
    def ensure_omega(self, r: Rolling, via: str | None = None) -> None:
        """ω of the rolling link from a point ``via`` of it with a velocity image."""
        cn = r.contact_name
        i = r.link
        if i in self.omega:
            return
        c = r.contact_label
        vj, _ = self.coincident(r.on, c)
        p = via or self.point_with_image(i, c, acc=False)
        assert p is not None
        self.V("angular_rate", (p, c, self.vimg[p], vj), f"ω{i}", role=Role.RESULT,
               note=f"No slip: the contact point of link {i} has the velocity of the surface's; "
                    f"ω{i} = V_{cn}{_n(p)}/R_{cn}{_n(p)}.")
        self.omega[i] = f"ω{i}"

    def rolling_rates(self, r: Rolling) -> None:
        """ω and α of the rolling link from the link it rolls on (Eqs. 3.13, 4.19)."""
        cn = r.contact_name
        i = r.link
        self.ensure_omega(r)
        if i in self.alpha:
            return
        _, al = self.contact_images(r)
        c = r.contact_label
        p = self.point_with_image(i, c)
        assert p is not None
        self.A("angular_rate", (p, c, self.aimg[p], al), f"α{i}", role=Role.RESULT,
               note=f"α{i} = A^t_{cn}{_n(p)}/R_{cn}{_n(p)}, its sense from the image.")
        self.alpha[i] = f"α{i}"

    # ---- the rules tried when a step waits ---------------------------------------------
    def roll(self, r: Rolling) -> bool:
        """Carry the rates over the contact r where one side is known; True when it did."""
        cn = r.contact_name
        i, j = r.link, r.on
        c = r.contact_label
        if c not in self.pc.values:
            return False
        if self.ready(j) and (i not in self.omega or i not in self.alpha):
            p = self.point_with_image(i, c)
            if p is None:
                return False
            self.ensure_omega(r, via=p)
            self.rolling_rates(r)
            return True
        if self.ready(i) and (j not in self.omega or j not in self.alpha):
            p = self.point_with_image(j, c)
            if p is None or j in self.omega:
                return False
            vi, _ = self.coincident(i, c)
            self.V("angular_rate", (p, c, self.vimg[p], vi), f"ω{j}", role=Role.RESULT,
                   note=f"No slip: the contact point of link {j} has the velocity of link {i}'s; "
                        f"ω{j} = V_{cn}{_n(p)}/R_{cn}{_n(p)}.")
            self.omega[j] = f"ω{j}"
            aj = self.contact_on(r)
            self.A("angular_rate", (p, c, self.aimg[p], aj), f"α{j}", role=Role.RESULT,
                   note=f"α{j} = A^t_{cn}{_n(p)}/R_{cn}{_n(p)}, its sense from the image.")
            self.alpha[j] = f"α{j}"
            return True
        return False

    def contact_on(self, r: Rolling) -> str:
        """``A_C(on) = A_C(link) − A^r``: the contact point of ``on`` from the rolling link."""
        cn = r.contact_name
        i, j = r.link, r.on
        c = r.contact_label
        _, ai = self.coincident(i, c)
        lab = f"{_aimg(f'{c}@{j}')}:r"
        if lab not in {o for st in self.a.steps for o in st.outputs}:
            ar = self.rolling_normal(r)
            self.A("subtract", (ai, ar), lab, role=Role.RESULT,
                   equation=VectorEquation((Term(f"A_{cn}{j}", U, U),),
                                           (Term(f"A_{cn}{i}"), Term(f"A_{cn}{i}/{j}^r", sign=-1)),
                                           case=1),
                   note=f"A_{cn}{j} = A_{cn}{i} − A_{cn}{i}/{j}^r (case 1).")
        return lab

    def known_on(self, k: str) -> list[tuple[str, str, Rolling | None]]:
        """Points of link k with a known velocity image: (label, image, contact or None)."""
        out: list[tuple[str, str, Rolling | None]] = [
            (p, self.vimg[p], None) for p in self.mech.links[k].points
            if p in self.vimg and p in self.aimg]
        for r in self.mech.rolling:
            c = r.contact_label
            if c not in self.pc.values:
                continue
            if r.link == k and self.ready(r.on):
                out.append((c, self.coincident(r.on, c)[0], r))
            elif r.on == k and self.ready(r.link) and r.link in self.omega:
                out.append((c, self.coincident(r.link, c)[0], r))
        return out

    def two_images(self, k: str) -> bool:
        """ω and α of link k from two of its points with known images (Mehmke, Sec. 3.5)."""
        if k == FRAME or k in self.omega or k not in self.anchor:
            return False
        pts = self.known_on(k)
        pair = next(((a, b) for n, a in enumerate(pts) for b in pts[n + 1:]
                     if self.apart(a[0], b[0])), None)
        if pair is None:
            return False
        (pa, va, ra), (pb, vb, rb) = pair
        self.V("angular_rate", (pa, pb, va, vb), f"ω{k}", role=Role.RESULT,
               note=f"ω{k} = V_{_n(pb)}{_n(pa)}/R_{_n(pb)}{_n(pa)}: two points of link {k} "
                    "with known images (no slip at a contact), its sense from the image.")
        self.omega[k] = f"ω{k}"

        def acc(p: str, r: Rolling | None) -> str:
            if r is None:
                return self.aimg[p]
            return self.contact_images(r)[1] if r.link == k else self.contact_on(r)

        aa, ab = acc(pa, ra), acc(pb, rb)
        self.A("angular_rate", (pa, pb, aa, ab), f"α{k}", role=Role.RESULT,
               note=f"α{k} = A^t_{_n(pb)}{_n(pa)}/R_{_n(pb)}{_n(pa)}, its sense from the image.")
        self.alpha[k] = f"α{k}"
        anc = self.anchor[k]
        if anc not in self.vimg:
            self.vimg[anc] = self.V(
                "velocity_difference", (va, f"ω{k}", pa, anc), _vimg(anc), role=Role.RESULT,
                note=f"V_{_n(anc)} = V_{_n(pa)} + ω{k} × R_{_n(anc)}{_n(pa)} (case 1).")
            self.aimg[anc] = self.A(
                "acceleration_difference", (aa, f"ω{k}", f"α{k}", pa, anc), _aimg(anc),
                role=Role.RESULT,
                note=f"A_{_n(anc)} = A_{_n(pa)} + A^n + A^t (case 1).")
        return True

    def unstick(self) -> bool:
        """Try every rule once; True when one of them drew something."""
        done = False
        for r in self.mech.rolling:
            done = self.roll(r) or done
        for k in self.mech.links:
            if k != FRAME and k not in self.omega:
                done = self.two_images(k) or done
        return done
