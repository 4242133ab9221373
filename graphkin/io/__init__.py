"""File formats at the edge of graphkin: DXF drawings (:mod:`graphkin.io.dxf`, needs ezdxf).

Nothing here is imported by ``import graphkin``; ezdxf is imported only when a
DXF is read or written (ezdxf is a dependency of graphkin).
"""
