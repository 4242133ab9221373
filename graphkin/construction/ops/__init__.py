"""The operations a construction step may perform, by name.

Each operation takes the arrays named by the step's ``inputs`` (any common
leading shape), the step's ``params`` and a tolerance, and returns a tuple of
arrays, one per output.  They are thin wrappers over :mod:`graphkin.geometry.ops`;
none of them loops over postures.

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 2.8 (cases 1-4), 3.4-3.5 and 4.2-4.3
(velocity and acceleration polygons and images).
"""

from __future__ import annotations

# the operations and kernels register themselves on import
from graphkin.construction.ops import compass, drives, kernels, points, polygons  # noqa: F401
from graphkin.construction.ops.registry import OPS, OUTPUT_KIND, op

# the compiled kernels' machinery, importable from here as before the split
from graphkin.construction.ops.runtime import (  # noqa: F401
    KERNELS,
    ORIGINATING,
    CompileInfo,
    Kernel,
    KernelFactory,
    Runtime,
    generic_kernel,
    kernel,
)

__all__ = ["OPS", "op", "OUTPUT_KIND"]
