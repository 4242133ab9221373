"""The live pages' "save the edited file": TOML written in the page, and its download.

One source for the mechanism pages (render/live_app.py) and the vector page
(render/live_vector_js.py): a value as TOML (a string quoted, an array, an
inline table), a table with its sub-tables and arrays of tables in the order
the file had them, and the download of the text as ``NAME-edited.toml``.

Examples
--------
>>> "function gkTomlTable(" in TOML_JS and "function gkDownload(" in TOML_JS
True
"""

from __future__ import annotations

__all__ = ["TOML_JS"]

TOML_JS = r"""
// ---- the edited file as TOML (render/live_toml_js.py) -------------------------------------
function gkTomlKey(k) { return /^[A-Za-z0-9_-]+$/.test(k) ? k : JSON.stringify(k); }
function gkTomlVal(v) {
  if (typeof v === "string") return JSON.stringify(v);
  if (typeof v === "number") return String(v);
  if (typeof v === "boolean") return String(v);
  if (Array.isArray(v)) return "[" + v.map(gkTomlVal).join(", ") + "]";
  return "{ " + Object.keys(v).map((k) => gkTomlKey(k) + " = " + gkTomlVal(v[k])).join(", ") + " }";
}
const gkIsTable = (v) => v !== null && typeof v === "object" && !Array.isArray(v);
function gkTomlTable(out, obj, path) {
  const simple = [], subs = [], arrs = [];
  for (const k of Object.keys(obj)) {
    const v = obj[k];
    if (gkIsTable(v)) subs.push(k);
    else if (Array.isArray(v) && v.length && v.every(gkIsTable)) arrs.push(k);
    else simple.push(k);
  }
  if (path.length && (simple.length || (!subs.length && !arrs.length))) {
    out.push("", "[" + path.map(gkTomlKey).join(".") + "]");
  }
  for (const k of simple) out.push(gkTomlKey(k) + " = " + gkTomlVal(obj[k]));
  for (const k of subs) gkTomlTable(out, obj[k], path.concat([k]));
  for (const k of arrs) {
    for (const e of obj[k]) {
      out.push("", "[[" + path.concat([k]).map(gkTomlKey).join(".") + "]]");
      for (const kk of Object.keys(e)) out.push(gkTomlKey(kk) + " = " + gkTomlVal(e[kk]));
    }
  }
}

// the text downloaded as "<file>-edited.toml" (the file's name without its folder)
function gkDownload(text, name) {
  const blob = new Blob([text], {type: "application/toml"});
  const a = document.createElement("a");
  a.href = URL.createObjectURL(blob);
  a.download = name.replace(/\.toml$/i, "").replace(/^.*[\\/]/, "") + "-edited.toml";
  document.body.appendChild(a); a.click(); a.remove();
  setTimeout(() => URL.revokeObjectURL(a.href), 1000);
}
"""
