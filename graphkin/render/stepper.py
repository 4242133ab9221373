"""The one-frame-at-a-time step page shared by the forces and gear layouts.

Each step of a recorded construction is one ``<section class='frame'>`` with its
drawing; the previous/next buttons and the arrow keys show one at a time
(``graphkin steps -d forces``, ``graphkin steps GEARFILE -d gears``).
"""

from __future__ import annotations

import html

__all__ = ["PAGER_JS", "frame_section"]

PAGER_JS = ("let k=0;const f=[...document.querySelectorAll('.frame')];"
            "function show(i){k=Math.max(0,Math.min(f.length-1,i));"
            "f.forEach((e,j)=>e.style.display=j===k?'block':'none');}"
            "document.getElementById('prev').onclick=()=>show(k-1);"
            "document.getElementById('next').onclick=()=>show(k+1);"
            "document.addEventListener('keydown',e=>{if(e.key==='ArrowLeft')show(k-1);"
            "if(e.key==='ArrowRight')show(k+1);});")
"""Previous/next buttons (ids ``prev``, ``next``) and the arrow keys step the frames."""


def frame_section(k: int, n: int, label: str, middle: str, svg: str) -> str:
    """Frame ``k`` of ``n``: its title, ``middle`` (already HTML) and the drawing.

    Examples
    --------
    >>> frame_section(0, 2, "P & Q", "<p>x</p>", "<?xml?><svg/>")[:60]
    "<section class='frame' id='step-0' style='display:block'><h2"
    """
    return (f"<section class='frame' id='step-{k}' style='display:"
            f"{'block' if k == 0 else 'none'}'><h2>Step {k + 1} of {n}: "
            f"{html.escape(label)}</h2>{middle}"
            f"<div class='fig'>{svg[svg.index('<svg'):]}</div></section>")
