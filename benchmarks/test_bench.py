"""pytest-benchmark timings of ``mech.sweep`` and the closed-form four-bar.

Not collected by the normal test run (``testpaths`` is ``tests`` and
``graphkin``).  Run::

    python -m pytest benchmarks/test_bench.py --benchmark-only -p no:cacheprovider

and compare the ``graphkin`` and ``closed form`` rows (``--benchmark-group-by=param``
puts the counts side by side).  Nothing about time is asserted.
"""

from __future__ import annotations

import importlib.util
import math
import pathlib

import numpy as np
import pytest

import graphkin

HERE = pathlib.Path(__file__).resolve().parent
BENCH = pathlib.Path(__file__).resolve().parent / "bench_fourbar.toml"


def _closed_form():
    spec = importlib.util.spec_from_file_location("fourbar_closed_form",
                                                  HERE / "fourbar_closed_form.py")
    assert spec is not None and spec.loader is not None
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


@pytest.fixture(scope="module")
def mech():
    if not BENCH.exists():
        pytest.skip("benchmarks/bench_fourbar.toml is missing")
    return graphkin.load(BENCH)


@pytest.mark.parametrize("count", [36, 360, 3600, 360_000])
def test_graphkin_sweep(benchmark, mech, count):
    sw = benchmark(mech.sweep, count=count)
    assert sw.valid.all()


@pytest.mark.parametrize("count", [36, 360, 3600, 360_000])
def test_closed_form(benchmark, mech, count):
    fb = _closed_form().fourbar_from_mechanism(mech)
    d = mech.drives[0]
    theta = d.value + 2 * math.pi * np.arange(count) / count
    cols = benchmark(fb.solve, theta, d.rate, d.rate2 or 0.0)
    assert np.isfinite(cols["omega_4"]).all()


def test_graphkin_first_sweep(benchmark, mech):
    """Building the constructions once (a fresh mechanism each round) and one sweep."""
    text = BENCH.read_text(encoding="utf-8")
    benchmark(lambda: graphkin.loads(text).sweep(count=3600))


def _designs():
    r3 = np.linspace(10.0, 14.0, 1000)
    r4 = np.linspace(9.0, 12.5, 1000)
    return {"links.3.C": np.stack([r3, 0 * r3], 1), "links.4.C": np.stack([r4, 0 * r4], 1)}


def test_graphkin_batch(benchmark, mech):
    """1000 designs x 360 postures in one graphkin.batch call."""
    dims = _designs()
    b = benchmark(graphkin.batch, mech, dims, count=360)
    assert b.valid.all()


def test_closed_form_batch(benchmark, mech):
    """The same 1000 designs x 360 postures in closed form, (M, N) arrays."""
    dims = _designs()
    fb = _closed_form().fourbar_batch(mech, dims)
    d = mech.drives[0]
    theta = d.value + 2 * math.pi * np.arange(360) / 360
    cols = benchmark(fb.solve, theta, d.rate, d.rate2 or 0.0)
    assert np.isfinite(cols["omega_4"]).all()


@pytest.mark.parametrize("extra", ["centers", "curvature"])
def test_graphkin_sweep_with(benchmark, mech, extra):
    """Centers or curvature over 3600 postures (compare with test_graphkin_sweep[3600])."""
    sw = benchmark(lambda: mech.sweep(count=3600, **{extra: True}))
    assert len(sw) == 3600
