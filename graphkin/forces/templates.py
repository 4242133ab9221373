"""The force operations' templates, for the JavaScript writer (the live page's force polygons).

Each template writes, through the one table of templates
(:data:`graphkin.construction.codegen.TEMPLATES`), the arithmetic of one
operation of :mod:`graphkin.forces.ops` on one posture: a force is carried
as its wrench rows ``(Fx, Fy, M)`` (M its moment about the origin), a line
as ``(a, b, c)``.  They are registered with ``python=False``: the Python
writer keeps calling the operations themselves, whose meaning is unchanged.

Where an operation divides by a quantity that vanishes at a dead center (the
pin on the known line of a three-force member, parallel lines of a force
polygon, three concurrent lines of a four-force member) the template returns
``null`` (:meth:`~graphkin.construction.codegen.Gen.bail_unless`): the page
says that equilibrium cannot be held there rather than show a number.

References
----------
Uicker, Pennock & Shigley, *Theory of Machines and Mechanisms*, 5th ed.,
Secs. 11.5-11.8 (two-, three- and four-force members, force polygons),
Sec. 12.4 (Eq. 12.18, d'Alembert's inertia force).
"""

from __future__ import annotations

from graphkin.construction.codegen import Gen, lit, template
from graphkin.construction.step import Step
from graphkin.tolerance import VERDICT_REL

__all__: list[str] = []

Rows = tuple[str, str, str]


def _wrench(gen: Gen, fx: str, fy: str, px: str, py: str) -> Rows:
    """The wrench of the force ``(fx, fy)`` through ``(px, py)``: moment ``P × F``."""
    fx, fy = gen.let(fx, "fx"), gen.let(fy, "fy")
    return fx, fy, gen.sub(gen.mul(px, fy), gen.mul(py, fx))


def _force(gen: Gen, label: str) -> Rows:
    fx, fy, m = gen.rows(label)
    return fx, fy, m


def _moment_about(gen: Gen, w: Rows, px: str, py: str) -> str:
    """``M - P × F``: the moment of the wrench about P (ccw positive)."""
    return gen.sub(w[2], gen.sub(gen.mul(px, w[1]), gen.mul(py, w[0])))


def _unit_on(gen: Gen, label: str) -> Rows:
    """The unit wrench on a line (a, b, c): along ``(b, -a)/n`` through its foot point."""
    a, b, c = gen.rows(label)
    n = gen.let(f"_sqrt({gen.add(gen.mul(a, a), gen.mul(b, b))})", "n")
    gen.bail_unless(f"{n} > 0.0")
    dx, dy = gen.let(f"{b} / {n}", "dx"), gen.let(f"{gen.neg(a)} / {n}", "dy")
    p0x = gen.let(f"{gen.neg(gen.mul(a, c))} / ({n} * {n})", "x")
    p0y = gen.let(f"{gen.neg(gen.mul(b, c))} / ({n} * {n})", "y")
    return _wrench(gen, dx, dy, p0x, p0y)


def _line_or_infinity(gen: Gen, w: Rows) -> Rows:
    """The line of action ``(-Fy, Fx, M)/|F|``; the line at infinity for a couple."""
    n = gen.let(f"_sqrt({gen.add(gen.mul(w[0], w[0]), gen.mul(w[1], w[1]))})", "n")
    return (gen.where(f"{n} > 0.0", f"{gen.neg(w[1])} / {n}", "0.0"),
            gen.where(f"{n} > 0.0", f"{w[0]} / {n}", "0.0"),
            gen.where(f"{n} > 0.0", f"{w[2]} / {n}", "1.0"))


def _concurrency(gen: Gen, l1: tuple[str, ...], l2: tuple[str, ...]) -> Rows:
    """Where two lines of action meet, ``[x, y, 1]``, or their point at infinity ``[., ., 0]``."""
    a1, b1, c1 = (gen.let(r, "l") for r in l1)
    a2, b2, c2 = (gen.let(r, "l") for r in l2)
    x = gen.let(gen.sub(gen.mul(b1, c2), gen.mul(c1, b2)), "x")
    y = gen.let(gen.sub(gen.mul(c1, a2), gen.mul(a1, c2)), "y")
    w = gen.let(gen.sub(gen.mul(a1, b2), gen.mul(b1, a2)), "w")
    n = gen.let(f"_sqrt({gen.add(gen.mul(x, x), gen.mul(y, y))})", "n")
    gen.bail_unless(f"{n} > 0.0 || _abs({w}) > 0.0")
    fin = f"_abs({w}) > {lit(1e-12)} * {n}"
    return (gen.where(fin, f"{x} / {w}", f"{x} / {n}"),
            gen.where(fin, f"{y} / {w}", f"{y} / {n}"), gen.where(fin, "1.0", "0.0"))


def _scaled(gen: Gen, w: Rows, k: str) -> Rows:
    k = gen.let(k, "k")
    return gen.mul(w[0], k), gen.mul(w[1], k), gen.mul(w[2], k)


def _minus(gen: Gen, a: Rows, b: Rows | None = None) -> Rows:
    """``-(a + b)`` (or ``-a``)."""
    if b is None:
        return gen.neg(a[0]), gen.neg(a[1]), gen.neg(a[2])
    return tuple(gen.neg(f"({gen.add(x, y)})") for x, y in zip(a, b))  # type: ignore[return-value]


def _gate(gen: Gen, den: str, size: str) -> None:
    """Return null unless ``den`` is clearly above round-off of ``size`` (a dead center)."""
    tol = gen.tol
    gen.bail_unless(f"_abs({den}) > {lit(tol.length_abs)} + {lit(1e3 * tol.length_rel)} * "
                    f"({size})")


@template("force_load", python=False)
def _load(gen: Gen, step: Step) -> None:
    px, py = gen.pt(step.inputs[0])
    fx, fy = (gen.num(float(v)) for v in step.params["force"])
    gen.put_rows(step.outputs[0], "force", *_wrench(gen, fx, fy, px, py))


@template("force_couple", python=False)
def _couple(gen: Gen, step: Step) -> None:
    gen.put_rows(step.outputs[0], "force", "0.0", "0.0", gen.num(float(step.params["torque"])))


@template("force_zero", python=False)
def _zero(gen: Gen, step: Step) -> None:
    gen.put_rows(step.outputs[0], "force", "0.0", "0.0", "0.0")


@template("force_inertia", python=False)
def _inertia(gen: Gen, step: Step) -> None:
    # -m A_G through G, with the inertia torque -I_G α added to its moment (Eq. 12.18)
    gp, ag, alpha = step.inputs
    gx, gy = gen.pt(gp)
    ax, ay, *_ = gen.rows(ag)
    m, i = gen.num(float(step.params["mass"])), gen.num(float(step.params["moment"]))
    fx, fy, mo = _wrench(gen, gen.neg(gen.mul(m, ax)), gen.neg(gen.mul(m, ay)), gx, gy)
    gen.put_rows(step.outputs[0], "force", fx, fy, gen.sub(mo, gen.mul(i, gen.scalar(alpha))))


@template("force_weight", python=False)
def _weight(gen: Gen, step: Step) -> None:
    gx, gy = gen.pt(step.inputs[0])
    m = gen.num(float(step.params["mass"]))
    g0, g1 = (gen.num(float(v)) for v in step.params["gravity"])
    gen.put_rows(step.outputs[0], "force", *_wrench(gen, gen.mul(m, g0), gen.mul(m, g1), gx, gy))


@template("force_resultant", python=False)
def _resultant(gen: Gen, step: Step) -> None:
    out = _force(gen, step.inputs[0])
    for lab in step.inputs[1:]:
        w = _force(gen, lab)
        out = (gen.add(out[0], w[0]), gen.add(out[1], w[1]), gen.add(out[2], w[2]))
    gen.put_rows(step.outputs[0], "force", *out)


def _negated(gen: Gen, step: Step) -> None:
    # action and reaction (Newton's third law), or the one force balancing the others
    gen.put_rows(step.outputs[0], "force", *_minus(gen, _force(gen, step.inputs[0])))


template("force_reverse", python=False)(_negated)
template("force_balance", python=False)(_negated)


@template("force_line", python=False)
def _line(gen: Gen, step: Step) -> None:
    # the line through P along d: (-dy, dx, px dy - py dx) / |d|
    px, py = gen.pt(step.inputs[0])
    dx, dy, *_ = gen.rows(step.inputs[1])
    n = gen.let(f"_sqrt({gen.add(gen.mul(dx, dx), gen.mul(dy, dy))})", "n")
    gen.bail_unless(f"{n} > 0.0")
    c = gen.sub(gen.mul(px, dy), gen.mul(py, dx))
    gen.put_rows(step.outputs[0], "line", f"{gen.neg(dy)} / {n}", f"{dx} / {n}", f"({c}) / {n}")


@template("force_line_of", python=False)
def _line_of(gen: Gen, step: Step) -> None:
    fx, fy, m = _force(gen, step.inputs[0])
    n = gen.let(f"_sqrt({gen.add(gen.mul(fx, fx), gen.mul(fy, fy))})", "n")
    gen.bail_unless(f"{n} > 0.0")
    gen.put_rows(step.outputs[0], "line", f"{gen.neg(fy)} / {n}", f"{fx} / {n}", f"{m} / {n}")


@template("force_three", python=False)
def _three(gen: Gen, step: Step) -> None:
    # a three-force member (Fig. 11.5e): Σ M_P = 0 gives F1 on its line, the polygon F2
    r_lab, line1, p = step.inputs
    r = _force(gen, r_lab)
    px, py = gen.pt(p)
    unit = _unit_on(gen, line1)
    den = gen.let(_moment_about(gen, unit, px, py), "d")
    _gate(gen, den, f"_abs({px}) + _abs({py}) + _abs({gen.rows(line1)[2]})")
    f1 = _scaled(gen, unit, f"{gen.neg(_moment_about(gen, r, px, py))} / {den}")
    f1 = tuple(gen.let(v, "f") for v in f1)  # type: ignore[assignment]
    f2 = _minus(gen, r, f1)
    x = _concurrency(gen, gen.rows(line1), _line_or_infinity(gen, r))
    for lab, rows in zip(step.outputs, (f1, f2, x)):
        gen.put_rows(lab, "force" if rows is not x else "point", *rows)


@template("force_slide_three", python=False)
def _slide_three(gen: Gen, step: Step) -> None:
    # both directions known (Ex 11.2): the polygon R + F1 + F2 = 0 gives both sizes
    r_lab, line1, n2 = step.inputs
    r = _force(gen, r_lab)
    nx, ny, *_ = gen.rows(n2)
    unit = _unit_on(gen, line1)
    det = gen.let(gen.sub(gen.mul(unit[0], ny), gen.mul(unit[1], nx)), "d")
    gen.bail_unless(f"_abs({det}) > {lit(gen.tol.angle)} * _sqrt({nx} * {nx} + {ny} * {ny})")
    k = f"{gen.neg(gen.sub(gen.mul(r[0], ny), gen.mul(r[1], nx)))} / {det}"
    f1 = tuple(gen.let(v, "f") for v in _scaled(gen, unit, k))
    f2 = tuple(gen.let(v, "f") for v in _minus(gen, r, f1))  # type: ignore[arg-type]
    x = _concurrency(gen, gen.rows(line1), _line_or_infinity(gen, f2))  # type: ignore[arg-type]
    for lab, rows in zip(step.outputs, (f1, f2, x)):
        gen.put_rows(lab, "force" if rows is not x else "point", *rows)


@template("force_four", python=False)
def _four(gen: Gen, step: Step) -> None:
    # a four-force member (Sec. 11.8): the three equilibrium equations, by Cramer's rule
    r = _force(gen, step.inputs[0])
    cols = [_unit_on(gen, lab) for lab in step.inputs[1:]]

    def det3(c1: Rows, c2: Rows, c3: Rows) -> str:
        (a1, a2, a3), (b1, b2, b3), (d1, d2, d3) = c1, c2, c3
        return (f"({a1} * ({b2} * {d3} - {b3} * {d2}) - {b1} * ({a2} * {d3} - {a3} * {d2}) "
                f"+ {d1} * ({a2} * {b3} - {a3} * {b2}))")

    det = gen.let(det3(cols[0], cols[1], cols[2]), "d")
    size = " + ".join(f"_abs({col[2]})" for col in cols)
    gen.bail_unless(f"_abs({det}) > {lit(gen.tol.angle)} * (1.0 + {size})")
    rhs = _minus(gen, r)
    rhs = tuple(gen.let(v, "q") for v in rhs)  # type: ignore[assignment]
    ks = [gen.let(f"{det3(*(rhs if j == k else cols[j] for j in range(3)))} / {det}", "k")
          for k in range(3)]
    fs = [_scaled(gen, col, k) for col, k in zip(cols, ks)]
    q = _concurrency(gen, gen.rows(step.inputs[1]), gen.rows(step.inputs[2]))
    for lab, rows in zip(step.outputs, (*fs, q)):
        gen.put_rows(lab, "force" if rows is not q else "point", *rows)


@template("force_drive_reaction", python=False)
def _drive_reaction(gen: Gen, step: Step) -> None:
    # the frame's force on the drive link at its pivot O balances ΣF (Ex 11.1 step 7)
    r = _force(gen, step.inputs[0])
    ox, oy = gen.pt(step.inputs[1])
    gen.put_rows(step.outputs[0], "force", *_wrench(gen, gen.neg(r[0]), gen.neg(r[1]), ox, oy))


@template("force_drive_torque", python=False)
def _drive_torque(gen: Gen, step: Step) -> None:
    # T_12 balances Σ M_O (Ex 11.1 step 7)
    r = _force(gen, step.inputs[0])
    ox, oy = gen.pt(step.inputs[1])
    gen.put_scalar(step.outputs[0], gen.neg(f"({_moment_about(gen, r, ox, oy)})"))


@template("force_drive_force", python=False)
def _drive_force(gen: Gen, step: Step) -> None:
    # a slider drive (Ex 12.3): the input force along u and the guide's normal force along n
    r = _force(gen, step.inputs[0])
    px, py = gen.pt(step.inputs[1])
    ux, uy, *_ = gen.rows(step.inputs[2])
    nx, ny, *_ = gen.rows(step.inputs[3])
    det = gen.let(gen.sub(gen.mul(ux, ny), gen.mul(uy, nx)), "d")
    gen.bail_unless(f"_abs({det}) > {lit(gen.tol.angle)}")
    f = gen.let(f"{gen.neg(gen.sub(gen.mul(r[0], ny), gen.mul(r[1], nx)))} / {det}", "k")
    drive = tuple(gen.let(v, "f") for v in _wrench(gen, gen.mul(ux, f), gen.mul(uy, f), px, py))
    gen.put_rows(step.outputs[0], "force", *drive)
    gen.put_rows(step.outputs[1], "force", *_minus(gen, r, drive))  # type: ignore[arg-type]


@template("force_along", python=False)
def _along(gen: Gen, step: Step) -> None:
    fx, fy, _ = _force(gen, step.inputs[0])
    ux, uy, *_ = gen.rows(step.inputs[1])
    gen.put_scalar(step.outputs[0], gen.add(gen.mul(fx, ux), gen.mul(fy, uy)))


@template("force_add_torques", python=False)
def _add_torques(gen: Gen, step: Step) -> None:
    out = gen.scalar(step.inputs[0])
    for lab in step.inputs[1:]:
        out = gen.add(out, gen.scalar(lab))
    gen.put_scalar(step.outputs[0], out)


# ---- friction (Sec. 11.10): the senses and the leant line, as graphkin.forces.ops ---------


def _sense_expr(gen: Gen, c: str, scale: str) -> str:
    """``sign(c)``, 0 within VERDICT_REL of ``scale`` (graphkin.tolerance.sign)."""
    zero = f"_abs({c}) <= {lit(VERDICT_REL)} * _abs({scale})"
    return gen.let(gen.where(zero, "0.0", gen.where(f"{c} > 0.0", "1.0", "-1.0")), "sg")


@template("force_scale", python=False)
def _scale(gen: Gen, step: Step) -> None:
    size = gen.num(float(step.params["size"]))
    parts = []
    for lab, kind in zip(step.inputs, step.params["kinds"]):
        if kind == "scale":
            parts.append(f"_abs({gen.scalar(lab)})")
        elif kind == "couple":
            parts.append(f"_abs({_force(gen, lab)[2]}) / {size}")
        elif kind == "rate":
            parts.append(f"_abs({gen.scalar(lab)}) * {size}")
        else:
            fx, fy, _ = _force(gen, lab)
            parts.append(f"_sqrt({gen.add(gen.mul(fx, fx), gen.mul(fy, fy))})")
    out = "0.0"
    for p in parts:
        out = gen.let(f"_maximum({out}, {p})", "m")
    gen.put_scalar(step.outputs[0], out)


def _on_block_dot(gen: Gen, step: Step) -> str:
    fx, fy, _ = _force(gen, step.inputs[0])
    nx, ny, *_ = gen.rows(step.inputs[1])
    c = gen.add(gen.mul(fx, nx), gen.mul(fy, ny))
    return c if step.params["block"] == "hi" else gen.neg(c)


@template("force_normal_sense", python=False)
def _normal_sense(gen: Gen, step: Step) -> None:
    gen.put_scalar(step.outputs[0], _sense_expr(gen, _on_block_dot(gen, step),
                                                gen.scalar(step.inputs[2])))


@template("force_friction_normal", python=False)
def _friction_normal(gen: Gen, step: Step) -> None:
    nx, ny, *_ = gen.rows(step.inputs[0])
    ux, uy, *_ = gen.rows(step.inputs[1])
    s = gen.scalar(step.inputs[2])
    mu = gen.num(float(step.params["mu"]))
    imp = step.params.get("impending")
    k = gen.mul(mu, gen.scalar(step.inputs[3]) if imp is None else gen.num(float(imp)))
    dx = gen.sub(gen.mul(s, nx), gen.mul(k, ux))
    dy = gen.sub(gen.mul(s, ny), gen.mul(k, uy))
    n = gen.let(f"_sqrt({gen.add(gen.mul(dx, dx), gen.mul(dy, dy))})", "n")
    rough = f"_abs({s}) > 0.0"
    gen.put_rows(step.outputs[0], "vector", gen.where(rough, f"{dx} / {n}", nx),
                 gen.where(rough, f"{dy} / {n}", ny))


@template("force_turned", python=False)
def _turned(gen: Gen, step: Step) -> None:
    c = _sense_expr(gen, _on_block_dot(gen, step), gen.scalar(step.inputs[2]))
    s = gen.scalar(step.inputs[3])
    gen.put_scalar(step.outputs[0], gen.where(f"{c} < 0.0", gen.where(
        f"_abs({s}) > 0.0", "1.0", "0.0"), "0.0"))


@template("force_impending", python=False)
def _impending(gen: Gen, step: Step) -> None:
    vpx, vpy, *_ = gen.rows(step.inputs[0])
    vqx, vqy, *_ = gen.rows(step.inputs[1])
    qx, qy, *_ = gen.rows(step.inputs[2])
    px, py, *_ = gen.rows(step.inputs[3])
    w = gen.scalar(step.inputs[4])
    ux, uy, *_ = gen.rows(step.inputs[5])
    dx, dy = gen.sub(px, qx), gen.sub(py, qy)
    rx = gen.sub(gen.sub(vpx, vqx), gen.neg(gen.mul(w, dy)))
    ry = gen.sub(gen.sub(vpy, vqy), gen.mul(w, dx))
    speed = gen.add(gen.mul(rx, ux), gen.mul(ry, uy))
    gen.put_scalar(step.outputs[0], _sense_expr(gen, speed, gen.scalar(step.inputs[6])))
