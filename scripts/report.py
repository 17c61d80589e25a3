#!/usr/bin/env python3
"""One page per fgimpact run: OUTPUT_DIR/report.html.

Usage:  python3 scripts/report.py OUTPUT_DIR [--out FILE]

One self-contained HTML file (no server, no network: the plots are inline
SVG, the pictures embedded as data URIs) that holds

  * the scene in one paragraph (parameters.prm, summary.json) and a
    picture: the section through the impact point to scale, the plate's
    metal/ceramic gradation and the ball;
  * the headline numbers (summary.json) with their error estimates where
    the run has them (Accuracy = converged, or Geometry/Adaptive
    refinement estimate: KEY_error_estimate, and its sources);
  * the validity verdicts with their numbers;
  * the contact force, the energies (stacked, with the balance error) and
    the deflections against time, from history.csv;
  * the pictures of scripts/render.sh (OUTPUT_DIR/pictures/*.png), when
    they were made;
  * the convergence table (convergence.csv) of a converged run, the
    runs of an adaptive one (adaptation.csv) and its estimate's checks
    (adaptive_estimate.csv);
  * for a study (study.csv): one row per case, linked to its directory.

fgimpact writes it at the end of every run (Output/Report); this script
writes it again on request, e.g. after scripts/render.sh.  Only Python's
standard library is needed.  The file is written to a temporary name and
renamed: a reader never sees half a report.  Exit 2 with one line for a
bad command line or a directory without summary.txt.
"""

import base64
import csv
import html
import json
import math
import os
import sys

# The headline numbers: summary key, label, unit.
HEADLINE = [
    ("peak_contact_force_N", "peak contact force", "N"),
    ("time_of_peak_force_us", "time of the peak force", "µs"),
    ("contact_duration_us", "contact duration", "µs"),
    ("departure_velocity_m_s", "departure velocity of the ball", "m/s"),
    ("max_midplane_deflection_um", "largest mid-plane deflection", "µm"),
    ("max_top_deflection_um", "largest top-face deflection", "µm"),
    ("max_approach_um", "largest approach of ball and plate", "µm"),
    ("max_indentation_um", "largest indentation α of the Hertz law", "µm"),
    ("max_hertz_indentation_um",
     "largest half-space Hertz estimate (F/K)^(2/3)", "µm"),
    ("max_contact_radius_mm", "largest contact radius", "mm"),
    ("permanent_indentation_um", "crater depth", "µm"),
    ("crater_diameter_mm", "crater diameter", "mm"),
    ("plastic_dissipation_J", "plastic work", "J"),
    ("max_equivalent_plastic_strain", "largest equivalent plastic strain", ""),
    ("von_mises_at_peak_MPa", "largest von Mises stress", "MPa"),
    ("principal_at_peak_MPa", "largest principal stress in the ceramic",
     "MPa"),
    ("probe_top_peak_von_mises_MPa", "top probe: peak von Mises", "MPa"),
    ("probe_mid_peak_von_mises_MPa", "mid-plane probe: peak von Mises",
     "MPa"),
    ("probe_bottom_peak_von_mises_MPa", "bottom probe: peak von Mises",
     "MPa"),
]

# The unit suffixes of summary keys, longest first.
UNIT_SUFFIXES = ["_m_s", "_MPa", "_us", "_um", "_mm", "_N", "_J"]

COLOURS = ["#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b"]


def fail(message):
    print("report.py: error: " + message, file=sys.stderr)
    sys.exit(2)


def parse_arguments(argv):
    if len(argv) > 1 and argv[1] in ("-h", "--help"):
        print(__doc__)
        sys.exit(0)
    args = argv[1:]
    out = None
    if "--out" in args:
        at = args.index("--out")
        if at + 1 >= len(args):
            fail("--out needs a file name")
        out = args[at + 1]
        del args[at:at + 2]
    if len(args) != 1:
        fail("give one output directory (see --help)")
    directory = args[0]
    if not any(os.path.isfile(os.path.join(directory, name))
               for name in ("summary.txt", "study.csv")):
        fail("%s has no summary.txt or study.csv (not an fgimpact output "
             "directory)" % directory)
    return directory, out or os.path.join(directory, "report.html")


def read_summary(directory):
    """summary.json's values (typed); summary.txt's where it is missing."""
    path = os.path.join(directory, "summary.json")
    if os.path.isfile(path):
        with open(path) as f:
            return json.load(f)
    values = {}
    with open(os.path.join(directory, "summary.txt")) as f:
        for line in f:
            if "=" in line and not line.startswith("#"):
                key, value = line.split("=", 1)
                values[key.strip()] = value.strip()
    return values


def read_prm(directory):
    """parameters.prm as {"Section/Entry": value}."""
    values, path = {}, []
    name = os.path.join(directory, "parameters.prm")
    if not os.path.isfile(name):
        return values
    with open(name) as f:
        for line in f:
            line = line.split("#", 1)[0].strip()
            if line.startswith("subsection "):
                path.append(line[len("subsection "):].strip())
            elif line == "end" and path:
                path.pop()
            elif line.startswith("set ") and "=" in line:
                key, value = line[4:].split("=", 1)
                values["/".join(path + [key.strip()])] = value.strip()
    return values


def read_csv(path):
    if not os.path.isfile(path):
        return []
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def number(value):
    try:
        x = float(value)
        return x if math.isfinite(x) else None
    except (TypeError, ValueError):
        return None


def fmt(x, digits=4):
    return "%.*g" % (digits, x) if x is not None else "—"


def nice_ticks(low, high, n=5):
    """Round tick values (1, 2, 5 x 10^k) covering [low, high]."""
    if not (math.isfinite(low) and math.isfinite(high)) or high <= low:
        high = low + 1.0
    raw = (high - low) / n
    power = 10 ** math.floor(math.log10(raw))
    step = min((s * power for s in (1, 2, 5, 10) if s * power >= raw),
               default=10 * power)
    first = math.floor(low / step) * step
    ticks = []
    t = first
    while t <= high + 1e-9 * step:
        ticks.append(0.0 if abs(t) < 1e-12 * step else t)
        t += step
    if ticks[-1] < high:
        ticks.append(ticks[-1] + step)
    return ticks


def svg_chart(title, xlabel, ylabel, series, stacked=False, width=470,
              height=270):
    """An inline SVG line chart (or stacked areas) of series, a list of
    (label, xs, ys).  The axes carry round ticks; the legend is on top."""
    rows = (len(series) + 3) // 4  # legend rows of 4
    left, right, top, bottom = 62, 12, 30 + 13 * rows, 42
    w, h = width - left - right, height - top - bottom
    ys_drawn, lower = [], None
    for _, xs, ys in series:
        if stacked:
            base = lower or [0.0] * len(ys)
            ys = [a + b for a, b in zip(base, ys)]
            ys_drawn.append((base, ys))
            lower = ys
        else:
            ys_drawn.append((None, ys))
    xs_all = [x for _, xs, _ in series for x in xs]
    ys_all = [y for base, ys in ys_drawn for y in ys + (base or [])]
    if not xs_all:
        return ""
    xt = nice_ticks(min(xs_all), max(xs_all))
    yt = nice_ticks(min(ys_all + [0.0]) if stacked else min(ys_all),
                    max(ys_all))
    sx = lambda x: left + w * (x - xt[0]) / (xt[-1] - xt[0])
    sy = lambda y: top + h * (1 - (y - yt[0]) / (yt[-1] - yt[0]))
    out = ['<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d" '
           'font-family="sans-serif" font-size="11">' % (width, height),
           '<text x="%d" y="14" font-size="13" font-weight="bold">%s</text>'
           % (left, html.escape(title))]
    for t in xt:
        out.append('<line x1="%.1f" y1="%d" x2="%.1f" y2="%d" stroke="#ddd"/>'
                   '<text x="%.1f" y="%d" text-anchor="middle">%s</text>'
                   % (sx(t), top, sx(t), top + h, sx(t), top + h + 14,
                      fmt(t, 6)))
    for t in yt:
        out.append('<line x1="%d" y1="%.1f" x2="%d" y2="%.1f" stroke="#ddd"/>'
                   '<text x="%d" y="%.1f" text-anchor="end">%s</text>'
                   % (left, sy(t), left + w, sy(t), left - 4, sy(t) + 4,
                      fmt(t, 6)))
    out.append('<rect x="%d" y="%d" width="%d" height="%d" fill="none" '
               'stroke="#444"/>' % (left, top, w, h))
    out.append('<text x="%.1f" y="%d" text-anchor="middle">%s</text>'
               % (left + w / 2, height - 6, html.escape(xlabel)))
    out.append('<text transform="translate(13,%.1f) rotate(-90)" '
               'text-anchor="middle">%s</text>'
               % (top + h / 2, html.escape(ylabel)))
    for k, ((label, xs, _), (base, ys)) in enumerate(zip(series, ys_drawn)):
        colour = COLOURS[k % len(COLOURS)]
        line = " ".join("%.1f,%.1f" % (sx(x), sy(y)) for x, y in zip(xs, ys))
        if stacked:
            back = " ".join("%.1f,%.1f" % (sx(x), sy(y))
                            for x, y in reversed(list(zip(xs, base))))
            out.append('<polygon points="%s %s" fill="%s" fill-opacity="0.75" '
                       'stroke="none"/>' % (line, back, colour))
        else:
            out.append('<polyline points="%s" fill="none" stroke="%s" '
                       'stroke-width="1.5"/>' % (line, colour))
        lx, ly = left + 100 * (k % 4), 20 + 13 * (k // 4)
        out.append('<rect x="%d" y="%d" width="10" height="10" fill="%s"/>'
                   '<text x="%d" y="%d">%s</text>'
                   % (lx, ly, colour, lx + 13, ly + 9, html.escape(label)))
    out.append("</svg>")
    return "".join(out)


def column(rows, name):
    return [number(r.get(name)) for r in rows]


def history_charts(directory):
    """The force, energy, balance error, deflection and force-approach
    charts of history.csv (SVG strings)."""
    rows = read_csv(os.path.join(directory, "history.csv"))
    if not rows:
        return []
    t = column(rows, "t_us")
    charts = [svg_chart("Contact force", "t (µs)", "F (N)",
                        [("contact force", t, column(rows, "contact_force_N"))])]
    parts = [(label, name) for label, name in [
        ("ball kinetic", "energy_impactor_J"),
        ("plate kinetic", "energy_plate_kinetic_J"),
        ("strain", "energy_strain_J"), ("contact", "energy_contact_J"),
        ("plastic work", "energy_plastic_J")] if name in rows[0]]
    charts.append(svg_chart(
        "Energies (stacked; the top is the total)", "t (µs)", "energy (J)",
        [(label, t, column(rows, name)) for label, name in parts],
        stacked=True))
    total = column(rows, "energy_total_J")
    if total[0]:
        charts.append(svg_chart(
            "Energy balance error", "t (µs)", "(E_total − E_0) / E_0",
            [("balance error", t, [(e - total[0]) / total[0] for e in total])]))
    deflections = [(label, t, column(rows, name)) for label, name in [
        ("mid-plane (a/2, b/2, h/2)", "midplane_deflection_um"),
        ("top face (a/2, b/2, h)", "top_deflection_um")] if name in rows[0]]
    charts.append(svg_chart("Deflection under the impact point", "t (µs)",
                            "w (µm)", deflections))
    if "approach_um" in rows[0]:
        touching = [r for r in rows if (number(r["contact_force_N"]) or 0) > 0]
        charts.append(svg_chart(
            "Force against the approach of ball and plate", "approach (µm)",
            "F (N)", [("in contact", column(touching, "approach_um"),
                       column(touching, "contact_force_N"))]))
    return [c for c in charts if c]


def section_picture(prm, summary):
    """The section y = b/2 to scale: the plate (its colour from metal on
    top to ceramic below, after the power law) and the ball touching it."""
    a = number(prm.get("Geometry/Length a")) or 0.2
    h = number(prm.get("Geometry/Thickness h")) or 0.02
    R = number(prm.get("Impactor/Radius")) or 0.015
    n = number(summary.get("power_law_index"))
    x0 = number(prm.get("Impactor/Impact point x"))
    x0 = a / 2 if x0 is None or x0 < 0 else x0
    scale = 560.0 / a
    width, top = 600, 20 + 2 * R * scale
    stops = []
    for k in range(11):  # metal fraction (z/h)^n, z from the bottom
        zeta = 1 - k / 10
        metal = zeta ** n if n not in (None, 0) else 1.0
        grey = (int(120 + 100 * (1 - metal)), int(140 + 80 * (1 - metal)),
                int(170 - 40 * (1 - metal)))
        stops.append('<stop offset="%.2f" stop-color="rgb(%d,%d,%d)"/>'
                     % (k / 10, *grey))
    return ('<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d" '
            'font-family="sans-serif" font-size="11"><defs><linearGradient '
            'id="fgm" x1="0" y1="0" x2="0" y2="1">%s</linearGradient></defs>'
            '<rect x="20" y="%.1f" width="%.1f" height="%.1f" fill="url(#fgm)"'
            ' stroke="#333"/><circle cx="%.1f" cy="%.1f" r="%.1f" '
            'fill="#bbb" fill-opacity="0.7" stroke="#333"/>'
            '<text x="24" y="%.1f">metal</text><text x="24" y="%.1f">ceramic'
            '</text><text x="%.1f" y="14" text-anchor="middle">ball, R = %s '
            'mm</text><text x="%.1f" y="%.1f" text-anchor="middle">section y '
            '= b/2 to scale: a = %s mm, h = %s mm</text></svg>'
            % (width, top + h * scale + 34, "".join(stops), top, a * scale,
               h * scale, 20 + x0 * scale, top - R * scale, R * scale,
               top + 12, top + h * scale - 4, 20 + x0 * scale, fmt(R * 1e3),
               width / 2, top + h * scale + 24, fmt(a * 1e3), fmt(h * 1e3)))


def scene_paragraph(prm, s):
    """The scene in one paragraph, from parameters.prm and summary.json."""
    g = lambda key, factor=1.0: fmt((number(prm.get(key)) or 0) * factor)
    faces = sorted({prm.get("Boundary conditions/Face %s" % f, "?")
                    for f in ("x min", "x max", "y min", "y max")})
    plastic = prm.get("Material/Plasticity", "none")
    text = (
        "A %s × %s × %s mm plate graded by the %s (index n = %s: metal, E = "
        "%s GPa, on top; ceramic, E = %s GPa, at the bottom), its side faces "
        "%s, struck by a %s ball of radius %s mm (%s kg) at %s m/s. "
        % (g("Geometry/Length a", 1e3), g("Geometry/Width b", 1e3),
           g("Geometry/Thickness h", 1e3), s.get("gradation", "power law"),
           fmt(number(s.get("power_law_index"))),
           g("Material/Metal Young's modulus", 1e-9),
           g("Material/Ceramic Young's modulus", 1e-9), " / ".join(faces),
           prm.get("Impactor/Material", "rigid"), g("Impactor/Radius", 1e3),
           fmt(number(s.get("impactor_mass_kg"))),
           g("Impactor/Initial velocity")))
    text += (
        "Contact: %s (%s refinement levels, element %s mm under the ball); "
        "metal %s; %s mesh of Q%s bricks%s (%s modelled, %s DoFs); time step "
        "%s µs (%s). "
        % (s.get("contact_model", "?"), s.get("contact_refinement_levels", 0),
           fmt(number(s.get("element_size_under_ball_mm"))),
           "elastic" if plastic == "none" else
           "J2-plastic (yield %s MPa)" % g("Material/Metal yield strength",
                                           1e-6),
           "×".join(prm.get("Geometry/Subdivisions " + c, "?")
                    for c in "xyz"), s.get("element_degree", 1),
           "" if s.get("element_technology", "standard") == "standard"
           else " with " + s["element_technology"],
           s.get("symmetry", "whole plate"), s.get("n_dofs", "?"),
           fmt(number(s.get("time_step_us"))), s.get("scheme", "?")))
    text += ("The run %s at t = %s µs in %s s." %
             (s.get("status", "?"), fmt(number(s.get("time_reached_us"))),
              fmt(number(s.get("wall_time_s")), 3)))
    return "<p>%s</p>" % html.escape(text)


def headline_table(s):
    """The headline numbers, with the run's error estimates (converged or
    adaptive)."""
    rows = []
    for key, label, unit in HEADLINE:
        value = number(s.get(key))
        if value is None:
            continue
        # The estimates (Accuracy = converged, Adaptive refinement
        # estimate) are named by the quantity, without the unit:
        # peak_contact_force_error_estimate for ..._N.
        stem = next((key[:-len(u)] for u in UNIT_SUFFIXES if key.endswith(u)),
                    key)
        estimate = number(s.get(stem + "_error_estimate"))
        sources = [(k[len(stem + "_error_estimate_"):].replace("_", " "),
                    number(v)) for k, v in s.items()
                   if k.startswith(stem + "_error_estimate_")]
        error = ("± %.2g %%" % (100 * estimate) if estimate is not None
                 else "")
        if sources:
            error += " <small>(%s)</small>" % ", ".join(
                "%s %.2g %%" % (name, 100 * v) for name, v in sources
                if v is not None)
        rows.append("<tr><td>%s</td><td class=n>%s</td><td>%s</td>"
                    "<td>%s</td><td><code>%s</code></td></tr>"
                    % (html.escape(label), fmt(value, 6), unit, error, key))
    return ("<table><tr><th>quantity</th><th>value</th><th>unit</th>"
            "<th>error estimate</th><th>summary key</th></tr>%s</table>"
            % "".join(rows))


def split_outside(text, separator):
    """text split at separator where it is outside parentheses."""
    parts, depth, start, i = [], 0, 0, 0
    while i < len(text):
        depth += {"(": 1, ")": -1}.get(text[i], 0)
        if depth == 0 and text.startswith(separator, i):
            parts.append(text[start:i])
            i += len(separator)
            start = i
            continue
        i += 1
    return parts + [text[start:]]


def validity_list(s):
    """summary.txt's validity line as one verdict per item, with the
    indices behind them."""
    text = s.get("validity") or ""
    items = []
    for part in split_outside(text, " | "):
        verdict, _, rest = part.partition(": ")
        for item in split_outside(rest, "; "):
            if item:
                items.append("<li><b>%s</b>: %s</li>"
                             % (html.escape(verdict), html.escape(item)))
    numbers = [(k, s[k]) for k in ("max_von_mises_over_yield",
                                   "max_principal_over_tensile_strength",
                                   "rigid_ball_modulus_excess",
                                   "max_equivalent_plastic_strain")
               if number(s.get(k)) is not None]
    warnings = s.get("warnings")
    return ("<ul>%s</ul><p>%s</p>%s" % (
        "".join(items), ", ".join("<code>%s</code> = %s" % (k, fmt(number(v)))
                                  for k, v in numbers),
        "<p><b>warnings</b>: %s</p>" % html.escape(str(warnings))
        if warnings else ""))


def csv_table(rows, link=None):
    """An HTML table of CSV rows; link(row) gives a cell's link target."""
    if not rows:
        return ""
    head = "".join("<th>%s</th>" % html.escape(k) for k in rows[0])
    body = []
    for r in rows:
        cells = []
        for k, v in r.items():
            v = html.escape(v or "")
            if link and k == list(r)[0]:
                v = '<a href="%s">%s</a>' % (html.escape(link(r)), v)
            cells.append("<td>%s</td>" % v)
        body.append("<tr>%s</tr>" % "".join(cells))
    return "<table><tr>%s</tr>%s</table>" % (head, "".join(body))


def pictures(directory):
    """The PNGs of scripts/render.sh, embedded."""
    folder = os.path.join(directory, "pictures")
    if not os.path.isdir(folder):
        return ("<p>No pictures yet: <code>scripts/render.sh %s</code> "
                "renders them, then <code>scripts/report.py</code> adds "
                "them here.</p>" % html.escape(directory))
    out = []
    for name in sorted(os.listdir(folder)):
        if name.endswith(".png"):
            with open(os.path.join(folder, name), "rb") as f:
                data = base64.b64encode(f.read()).decode()
            out.append('<figure><img src="data:image/png;base64,%s" '
                       'width="480"><figcaption>%s</figcaption></figure>'
                       % (data, html.escape(name)))
    return "".join(out)


STYLE = """body{font-family:sans-serif;max-width:1000px;margin:auto;
padding:1em;color:#222}table{border-collapse:collapse;margin:0.5em 0}
td,th{border:1px solid #ccc;padding:2px 6px;font-size:13px}
td.n{text-align:right;font-family:monospace}th{background:#eee}
figure{display:inline-block;margin:4px}svg{margin:4px}
figcaption{font-size:12px;text-align:center}h2{border-bottom:1px solid #aaa}
"""


def case_link(directory, row):
    """A study row's link: the case's report, else its summary."""
    case = next(iter(row.values()))
    name = "case_%03d" % int(case) if case.isdigit() else case
    for target in ("report.html", "summary.txt"):
        if os.path.isfile(os.path.join(directory, name, target)):
            return name + "/" + target
    return name


def page(directory):
    """The report's HTML text."""
    has_summary = os.path.isfile(os.path.join(directory, "summary.txt"))
    s = read_summary(directory) if has_summary else {}
    prm = read_prm(directory)
    title = "fgimpact run: %s" % os.path.basename(
        os.path.abspath(directory).rstrip("/"))
    parts = ["<!DOCTYPE html><html><head><meta charset=\"utf-8\"><title>%s"
             "</title><style>%s</style></head><body><h1>%s</h1>"
             % (html.escape(title), STYLE, html.escape(title))]
    provenance = s.get("provenance") or {}
    if provenance:
        parts.append("<p><small>%s</small></p>" % html.escape(
            "; ".join("%s %s" % kv for kv in provenance.items())))
    study = read_csv(os.path.join(directory, "study.csv"))
    if study:
        # The case, the study's entries (Section/Entry), the status and the
        # headline numbers; study.csv has every key.
        keep = [k for k in study[0] if k == "case" or "/" in k
                or k == "status" or k in dict((h[0], 0) for h in HEADLINE)]
        parts.append("<h2>Study: one row per case</h2>")
        parts.append(csv_table([{k: r[k] for k in keep} for r in study],
                               lambda r: case_link(directory, r)))
    if prm and has_summary:
        parts.append("<h2>Scene</h2>" + scene_paragraph(prm, s))
        parts.append(section_picture(prm, s))
    if not has_summary:  # a study's directory: its cases only
        return "".join(parts) + "</body></html>\n"
    parts.append("<h2>Headline numbers</h2>" + headline_table(s))
    parts.append("<h2>Validity</h2>" + validity_list(s))
    charts = history_charts(directory)
    if charts:
        parts.append("<h2>Time histories</h2>" + "".join(charts))
    convergence = read_csv(os.path.join(directory, "convergence.csv"))
    if convergence:
        parts.append("<h2>Convergence (Accuracy = converged)</h2>")
        parts.append(csv_table(convergence))
    adaptation = read_csv(os.path.join(directory, "adaptation.csv"))
    if adaptation:
        checks = read_csv(os.path.join(directory, "adaptive_estimate.csv"))
        parts.append("<h2>Adaptive mesh (Geometry/Adaptive refinement "
                     "cycles)</h2><p>The pilot runs, then the final run (the "
                     "numbers above). The change over the last cycle is no "
                     "error bound%s</p>" % (
                         ": the error estimates above come from the check "
                         "runs below, one source each." if checks else
                         ": this run has no estimate (Geometry/Adaptive "
                         "refinement estimate)."))
        parts.append(csv_table(adaptation))
        if checks:
            parts.append("<h3>Error estimate: the final run and its check "
                         "runs (adaptive_estimate.csv)</h3>")
            parts.append(csv_table(checks))
    parts.append("<h2>Pictures</h2>" + pictures(directory))
    parts.append("</body></html>\n")
    return "".join(parts)


def write(directory, out):
    """The report of directory into out, atomically."""
    text = page(directory)
    temporary = out + ".tmp"
    with open(temporary, "w", encoding="utf-8") as f:
        f.write(text)
    os.replace(temporary, out)
    print(out)


def main(argv):
    directory, out = parse_arguments(argv)
    # A study: each case's report first, so that the study's rows link them.
    if os.path.isfile(os.path.join(directory, "study.csv")):
        for name in sorted(os.listdir(directory)):
            case = os.path.join(directory, name)
            if name.startswith("case_") and os.path.isfile(
                    os.path.join(case, "summary.txt")):
                write(case, os.path.join(case, "report.html"))
    write(directory, out)


if __name__ == "__main__":
    main(sys.argv)
