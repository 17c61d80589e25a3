#!/usr/bin/env pvpython
"""Render the standard pictures of an fgimpact run with ParaView.

Usage:  pvpython scripts/render.py OUTPUT_DIR [--out DIR] [--frames N]
        (headless: xvfb-run -a pvpython scripts/render.py OUTPUT_DIR; Debian's
        ParaView 5.11 crashed with --force-offscreen-rendering)

Reads OUTPUT_DIR/solution.pvd (and sphere.pvd, contact.pvd, summary.txt) and
writes into OUTPUT_DIR/pictures (or --out):

  deformed_von_mises.png  the deformed plate (displacement magnified so the
                          largest deflection is 5 % of the plate's length)
                          and the ball, coloured by von Mises stress (MPa),
                          at the peak contact force
  deformed_sigma_zz.png   the same, coloured by sigma_zz (MPa)
  section.png             the section y = b/2 through the impact point,
                          coloured by von Mises stress (MPa), at the peak
  section_contact_von_mises.png, section_contact_sigma_zz.png
                          the same section at the contact's scale (3 largest
                          contact radii each side, true geometry), the
                          plastic zone shaded, the ball outlined
  contact_pressure.png    the contact pressure (MPa) on the top face seen from
                          above, interpolated between the contact nodes
                          (dots), with isobars at 25, 50 and 75 % of the
                          run's largest, at the peak (resolved contact only)
  plastic_strain.png      the equivalent plastic strain (when the files
                          hold it)
  animation/frame_NNNN.png  the deformed plate over the run (--frames, 0: none),
                          one frame per distinct snapshot time (at most
                          --frames, evenly spread over the run)
  animation.avi           the frames as a movie (Motion JPEG, 8 frames/s;
                          VTK's FFMPEG writer; animation.ogv, Theora, where
                          VTK has no FFMPEG)
  scene.pvsm              a ParaView state with the deformed plate and the
                          ball, opening at the peak snapshot, its time
                          annotated (5 sources, no helpers): File > Load State, choose
                          "Search files under specified directory" and this
                          OUTPUT_DIR to open it on any machine
  colours.csv             per picture: the field, its colour map and range,
                          and the picture's own data range

Every picture has the time in us and the scene (the output directory and the
peak force of summary.txt) in its title, and a colour bar with the unit and
the range.  One colour rule per field, stills and frames alike, linear:
sigma_* diverging and centred on 0 (-M to M, M its largest magnitude over
the run), every other field sequential from 0 to its largest value over the
run.
Exit 2 with one line on a bad command line or a directory without
solution.pvd.
"""

import argparse
import math
import os
import sys


def fail(message):
    sys.stderr.write("render.py: " + message + "\n")
    sys.exit(2)


def parse_arguments():
    parser = argparse.ArgumentParser(
        description="Render the standard pictures of an fgimpact run.")
    parser.add_argument("directory", help="the run's Output/Directory")
    parser.add_argument("--out", help="where to write (default "
                        "DIRECTORY/pictures)")
    parser.add_argument("--frames", type=int, default=24,
                        help="animation frames (0: no animation)")
    parser.add_argument("--size", type=int, nargs=2, default=[1200, 700],
                        metavar=("W", "H"), help="picture size in pixels")
    args = parser.parse_args()
    if not os.path.isfile(os.path.join(args.directory, "solution.pvd")):
        fail(args.directory + " has no solution.pvd (set Output/VTU "
             "interval or Output/Snapshot times)")
    if args.frames < 0:
        fail("--frames must be >= 0")
    return args


def summary(directory):
    """summary.txt's keys and values (strings); empty if missing."""
    values = {}
    path = os.path.join(directory, "summary.txt")
    if os.path.isfile(path):
        for line in open(path):
            if " = " in line and not line.startswith("#"):
                key, value = line.split(" = ", 1)
                values[key.strip()] = value.strip()
    return values


def history_column(directory, name):
    """(t_us, value) pairs of a history.csv column; [] if missing."""
    import csv
    path = os.path.join(directory, "history.csv")
    if not os.path.isfile(path):
        return []
    rows = list(csv.DictReader(open(path)))
    if not rows or name not in rows[0]:
        return []
    return [(float(r["t_us"]), float(r[name])) for r in rows]


def interpolate(pairs, t):
    """Linear interpolation in (t, value) pairs sorted by t."""
    for (t0, v0), (t1, v1) in zip(pairs, pairs[1:]):
        if t0 <= t <= t1:
            return v0 + (v1 - v0) * (t - t0) / (t1 - t0) if t1 > t0 else v0
    return pairs[-1][1] if t > pairs[-1][0] else pairs[0][1]


def pvd_times(path):
    """The timestep values (us) of a PVD file, in its order."""
    import re
    return [float(t) for t in
            re.findall(r'timestep="([^"]+)"', open(path).read())]


def frame_times(times, n):
    """At most n distinct snapshot times, evenly spread over the run."""
    chosen = []
    for k in range(n):
        t = times[0] + (times[-1] - times[0]) * k / max(n - 1, 1)
        t = min(times, key=lambda s: abs(s - t))
        if t not in chosen:
            chosen.append(t)
    return chosen


def write_movie(frames, out, rate=8):
    """The PNG frames as OUT/animation.avi (Motion JPEG, VTK's FFMPEG
    writer) or, without it, OUT/animation.ogv (Theora); its path."""
    from vtkmodules.vtkIOImage import vtkPNGReader
    try:
        from vtkmodules.vtkIOFFMPEG import vtkFFMPEGWriter as Writer
        path = os.path.join(out, "animation.avi")
    except ImportError:
        from vtkmodules.vtkIOOggTheora import vtkOggTheoraWriter as Writer
        path = os.path.join(out, "animation.ogv")
    reader = vtkPNGReader()
    reader.SetFileName(frames[0])
    reader.Update()
    writer = Writer()
    writer.SetInputConnection(reader.GetOutputPort())
    writer.SetFileName(path)
    writer.SetRate(rate)
    writer.SetQuality(2)
    writer.Start()
    for frame in frames:
        reader.SetFileName(frame)
        reader.Modified()
        reader.Update()
        writer.Write()
    writer.End()
    if writer.GetError():
        fail("the movie %s could not be written" % path)
    return path


def save_state(path, directory, scene_view):
    """A clean ParaView state (PATH): the plate's solution.pvd warped by the
    pictures' factor and coloured as scene_view says, the ball (sphere.pvd)
    placed as in the pictures, a title and the time (an annotation that
    follows the time), the camera of the 3D pictures, and the animation at
    the peak snapshot.  Built in a new session: the pictures' helpers
    (sections, thresholds, the pressure map) are not in it."""
    from paraview import simple as pv
    v = scene_view
    pv.ResetSession()
    plate = pv.PVDReader(registrationName="solution.pvd",
                         FileName=os.path.join(directory, "solution.pvd"))
    warp = pv.WarpByVector(registrationName="plate (displacement x %.0f)"
                           % v["factor"], Input=plate,
                           Vectors=["POINTS", "displacement_m"],
                           ScaleFactor=v["factor"])
    view = pv.CreateView("RenderView")
    view.ViewSize = v["size"]
    view.Background = [1, 1, 1]
    try:
        view.UseColorPaletteForBackground = 0
    except AttributeError:
        pass
    display = pv.Show(warp, view)
    pv.ColorBy(display, ("POINTS", v["field"]))
    lut = pv.GetColorTransferFunction(v["field"])
    lut.ApplyPreset(v["preset"], True)
    lut.RescaleTransferFunction(v["low"], v["high"])
    lut.AutomaticRescaleRangeMode = "Never"
    display.SetScalarBarVisibility(view, True)
    bar = pv.GetScalarBar(lut, view)
    bar.Title, bar.ComponentTitle = v["label"], ""
    bar.TitleColor = bar.LabelColor = [0, 0, 0]
    sphere_pvd = os.path.join(directory, "sphere.pvd")
    if os.path.isfile(sphere_pvd):
        sphere = pv.PVDReader(registrationName="sphere.pvd",
                              FileName=sphere_pvd)
        if v["ball_translate"] is None:
            ball = pv.WarpByVector(registrationName="ball", Input=sphere,
                                   Vectors=["POINTS", "displacement_m"],
                                   ScaleFactor=v["factor"])
        else:
            ball = pv.Transform(registrationName="ball", Input=sphere)
            ball.Transform = "Transform"
            ball.Transform.Translate = v["ball_translate"]
        ball_display = pv.Show(ball, view)
        ball_display.ColorArrayName = [None, ""]
        ball_display.DiffuseColor = ball_display.AmbientColor = [0.75, 0.75,
                                                                 0.8]
        ball_display.Opacity = 0.35
    title = pv.Text(registrationName="title", Text=v["title"])
    title_display = pv.Show(title, view)
    title_display.Color = [0, 0, 0]
    title_display.FontSize = 14
    title_display.WindowLocation = "Upper Center"
    clock = pv.AnnotateTimeFilter(registrationName="time", Input=plate)
    clock.Format = "t = {time:.2f} µs"
    clock_display = pv.Show(clock, view)
    clock_display.Color = [0, 0, 0]
    clock_display.FontSize = 14
    clock_display.WindowLocation = "Lower Center"
    view.CameraPosition = v["camera"][0]
    view.CameraFocalPoint = v["camera"][1]
    view.CameraViewUp = v["camera"][2]
    view.CameraParallelScale = v["camera"][3]
    animation = pv.GetAnimationScene()
    animation.UpdateAnimationUsingDataTimeSteps()
    animation.AnimationTime = v["time"]
    view.ViewTime = v["time"]
    pv.SaveState(path)
    return path


def main():
    args = parse_arguments()
    # Imported here: --help and the argument checks work without ParaView.
    from paraview import simple as pv

    directory = os.path.abspath(args.directory)
    out = os.path.abspath(args.out or os.path.join(directory, "pictures"))
    os.makedirs(out, exist_ok=True)
    keys = summary(directory)
    scene = os.path.basename(directory.rstrip("/"))
    if "peak_contact_force_N" in keys:
        scene += ", peak force %.0f N" % float(keys["peak_contact_force_N"])
    times = pvd_times(os.path.join(directory, "solution.pvd"))
    t_peak = float(keys.get("time_of_peak_force_us", "nan"))
    if math.isnan(t_peak):
        t_peak = times[len(times) // 2]
    # The snapshot nearest the peak (the peak's own one if written).
    t_show = min(times, key=lambda t: abs(t - t_peak))

    plate = pv.PVDReader(FileName=os.path.join(directory, "solution.pvd"))
    plate.UpdatePipelineInformation()
    arrays = plate.PointData.keys()
    if "displacement_m" not in arrays:
        fail("solution.pvd has no displacement_m (Output/Fields)")

    # The magnification: the largest |u| over the run -> 5 % of the length.
    bounds = plate.GetDataInformation().GetBounds()
    length = bounds[1] - bounds[0]
    largest = 0.0
    for t in times:
        plate.UpdatePipeline(t)
        r = plate.PointData["displacement_m"].GetRange(-1)
        largest = max(largest, r[1])
    factor = 0.05 * length / largest if largest > 0 else 1.0

    warp = pv.WarpByVector(Input=plate, Vectors=["POINTS", "displacement_m"],
                           ScaleFactor=factor)
    # The ball: with a resolved contact (contact.pvd) it touches the plate
    # where the plate is, so it is warped like the plate; a Hertz model's
    # indentation is a law, not geometry (magnified, the ball would sink
    # into the plate), so there the ball rests on the magnified top node:
    # moved by the factor times history.csv's top deflection.
    ball = None
    resolved = os.path.isfile(os.path.join(directory, "contact.pvd"))
    top = history_column(directory, "top_deflection_um")
    if os.path.isfile(os.path.join(directory, "sphere.pvd")):
        sphere = pv.PVDReader(FileName=os.path.join(directory, "sphere.pvd"))
        if resolved or not top:
            ball = pv.WarpByVector(Input=sphere,
                                   Vectors=["POINTS", "displacement_m"],
                                   ScaleFactor=factor)
        else:
            ball = pv.Transform(Input=sphere)
            ball.Transform = "Transform"

    # Said in the titles: how the ball is placed.
    ball_note = ("" if ball is None or resolved or not top else
                 "\nthe ball rests on the magnified top node (the Hertz "
                 "indentation is a law, not drawn)")

    def place_ball(t):
        if ball is not None and not resolved and top:
            ball.Transform.Translate = [0, 0, -factor * 1e-6 *
                                        interpolate(top, t)]

    view = pv.CreateView("RenderView")
    view.ViewSize = args.size
    view.Background = [1, 1, 1]
    view.OrientationAxesVisibility = 1
    # ParaView 5.11: a white background needs dark text.
    try:
        view.UseColorPaletteForBackground = 0
    except AttributeError:
        pass
    title = pv.Text(Text="")
    title_display = pv.Show(title, view)
    title_display.Color = [0, 0, 0]
    title_display.FontSize = 14
    title_display.WindowLocation = "Upper Center"
    # The colour rule and ranges, below the plate: on the colour bar's
    # (vertical) title they ran over its tick labels.
    note = pv.Text(Text="")
    note_display = pv.Show(note, view)
    note_display.Color = [0, 0, 0]
    note_display.FontSize = 12
    note_display.WindowLocation = "Lower Center"

    # One colour rule per field, for the stills and the animation alike:
    # a signed stress (sigma_*) on a diverging map centred on 0, from -M to
    # M with M its largest magnitude over the run; every other field (von
    # Mises, plastic strain, contact pressure, |u|) >= 0 on a sequential
    # map from 0 to its largest value over the run.  Linear colours; the
    # bar states the range and the picture's own data range, and
    # colours.csv lists them (scripts/check_render.sh reads it back).
    def run_range(source, field, source_times):
        component = -1 if field == "displacement_m" else 0
        low, high = math.inf, -math.inf
        for t in source_times:
            source.UpdatePipeline(t)
            r = source.PointData[field].GetRange(component)
            low, high = min(low, r[0]), max(high, r[1])
        return low, high

    def shown_range(source, field, t):
        component = -1 if field == "displacement_m" else 0
        source.UpdatePipeline(t)
        return source.PointData[field].GetRange(component)

    rows = []

    def colour(display, field, label, picture, source, source_times, t):
        # One colour bar: the previous field's goes.
        for name in colour.shown:
            pv.HideScalarBarIfNotNeeded(pv.GetColorTransferFunction(name),
                                        view)
            pv.GetScalarBar(pv.GetColorTransferFunction(name),
                            view).Visibility = 0
        colour.shown = [field]
        pv.ColorBy(display, ("POINTS", field))
        lut = pv.GetColorTransferFunction(field)
        lut.UseLogScale = 0
        smallest, largest = run_range(source, field, source_times)
        signed = field.startswith("sigma_")
        if signed:
            lut.ApplyPreset("Cool to Warm", True)
            top = max(abs(smallest), abs(largest))
            low, high = -top, top
            rule = "diverging, centred on 0"
        else:
            lut.ApplyPreset("Viridis (matplotlib)", True)
            low, high = 0.0, largest
            rule = "sequential from 0"
        if high <= low:
            high = low + 1.0
        lut.RescaleTransferFunction(low, high)
        lut.AutomaticRescaleRangeMode = "Never"
        here = shown_range(source, field, t)
        note.Text = "%s: %s, [%.3g, %.3g] over the run; here [%.3g, %.3g]" % (
            label, rule, low, high, here[0], here[1])
        display.SetScalarBarVisibility(view, True)
        bar = pv.GetScalarBar(lut, view)
        bar.Title = label
        bar.ComponentTitle = ""
        bar.TitleColor = [0, 0, 0]
        bar.LabelColor = [0, 0, 0]
        rows.append((picture, field, "diverging" if signed else "sequential",
                     low, high, here[0], here[1]))

    colour.shown = []

    def set_title(text, t):
        title.Text = "%s\nt = %.2f µs  (%s)" % (text, t, scene)

    def camera_3d():
        view.CameraPosition = [bounds[0] - 0.3 * length,
                               bounds[2] - 1.2 * length,
                               bounds[5] + 0.45 * length]
        view.CameraFocalPoint = [0.5 * (bounds[0] + bounds[1]),
                                 0.5 * (bounds[2] + bounds[3]),
                                 0.5 * (bounds[4] + bounds[5])]
        view.CameraViewUp = [0, 0, 1]
        view.ResetCamera(False)
        pv.GetActiveCamera().Dolly(1.5)

    written = []

    def save(name):
        path = os.path.join(out, name)
        pv.SaveScreenshot(path, view, ImageResolution=args.size)
        written.append(path)
        return path

    def contact_scale_sections(origin, top_face):
        """The section through the impact point at the contact's scale:
        the true geometry (displacement x 1: magnified, the contact would
        be distorted), 3 largest contact radii (summary.txt) each side,
        von Mises and sigma_zz, the plastic zone (equivalent plastic strain
        above 1e-6) and the ball's section (resolved contact) outlined."""
        radius = 1e-3 * float(keys.get("max_contact_radius_mm", "nan"))
        if not (math.isfinite(radius) and radius > 0):
            return
        true_plate = pv.WarpByVector(Input=plate,
                                     Vectors=["POINTS", "displacement_m"],
                                     ScaleFactor=1.0)
        near = pv.Slice(Input=true_plate)
        near.SliceType = "Plane"
        # Just beside the mesh plane y = b/2: through the cells, not along
        # their faces (whose two sides would each give a polygon).
        near.SliceType.Origin = [origin[0], origin[1] + 1e-3 * radius,
                                 origin[2]]
        near.SliceType.Normal = [0, 1, 0]
        near_display = pv.Show(near, view)
        outlines = []
        # The plastic zone: the cells whose plastic strain (constant in a
        # cell) is above 0, as summary.txt's plastic zone is measured,
        # shaded white over the colours (an isoline of the nodal field
        # would reach one element further out; the outline of cells of two
        # refinement levels has T-junctions).
        plastic = "equivalent_plastic_strain" in fields
        zone = None
        if plastic:
            zone = pv.Threshold(Input=near)
            zone.Scalars = ["POINTS", "equivalent_plastic_strain"]
            zone.LowerThreshold = 1e-12
            zone.UpperThreshold = 1e30
            zone.ThresholdMethod = "Between"
            zone.AllScalars = 1
            zone = pv.Transform(Input=zone)
            zone.Transform = "Transform"
            zone.Transform.Translate = [0, -0.05 * radius, 0]
            zone_display = pv.Show(zone, view)
            zone_display.ColorArrayName = [None, ""]
            zone_display.AmbientColor = zone_display.DiffuseColor = [1, 1, 1]
            zone_display.Opacity = 0.35
        if resolved and ball is not None:
            true_ball = pv.WarpByVector(Input=sphere,
                                        Vectors=["POINTS", "displacement_m"],
                                        ScaleFactor=1.0)
            cut = pv.Slice(Input=true_ball)
            cut.SliceType = "Plane"
            cut.SliceType.Origin = list(origin)
            cut.SliceType.Normal = [0, 1, 0]
            outlines.append(cut)
        # Moved a little towards the camera: lines in the section's plane
        # would hide behind its surface.
        outlines = [pv.Transform(Input=outline) for outline in outlines]
        for outline in outlines:
            outline.Transform = "Transform"
            outline.Transform.Translate = [0, -0.05 * radius, 0]
            d = pv.Show(outline, view)
            d.ColorArrayName = [None, ""]
            d.AmbientColor = d.DiffuseColor = [0, 0, 0]
            d.LineWidth = 2
        if ball_display is not None:
            pv.Hide(ball, view)
        focus = [origin[0], origin[1], top_face - 1.2 * radius]
        view.CameraPosition = [focus[0], focus[1] - 10 * radius, focus[2]]
        view.CameraFocalPoint = focus
        view.CameraViewUp = [0, 0, 1]
        view.CameraParallelProjection = 1
        view.CameraParallelScale = 1.8 * radius
        for field, label, name in [
                ("von_mises_MPa", "von Mises stress (MPa)",
                 "section_contact_von_mises.png"),
                ("sigma_zz_MPa", "sigma_zz (MPa)",
                 "section_contact_sigma_zz.png")]:
            if field not in fields:
                continue
            colour(near_display, field, label, name, plate, times, t_show)
            set_title("Section through the impact point at the contact's "
                      "scale (a = %.3g mm; true geometry)%s" %
                      (1e3 * radius, "; plastic zone shaded white" if
                       plastic else ""), t_show)
            save(name)
        for source in [near] + outlines + ([zone] if zone else []):
            pv.Hide(source, view)
        if ball_display is not None:
            pv.Show(ball, view)

    view.ViewTime = t_show
    place_ball(t_show)
    plate_display = pv.Show(warp, view)
    ball_display = None
    if ball is not None:
        ball_display = pv.Show(ball, view)
        ball_display.ColorArrayName = [None, ""]
        ball_display.DiffuseColor = [0.75, 0.75, 0.8]
        ball_display.AmbientColor = [0.75, 0.75, 0.8]
        ball_display.Opacity = 0.35
    camera_3d()
    fields = warp.PointData.keys()
    pictures = [("von_mises_MPa", "von Mises stress (MPa)",
                 "deformed_von_mises.png"),
                ("sigma_zz_MPa", "sigma_zz (MPa)", "deformed_sigma_zz.png"),
                ("equivalent_plastic_strain", "equivalent plastic strain (-)",
                 "plastic_strain.png")]
    for field, label, name in pictures:
        if field in fields:
            colour(plate_display, field, label, name, plate, times, t_show)
            set_title("Deformed plate (displacement x %.0f), %s%s" %
                      (factor, label, ball_note), t_show)
            save(name)

    # The section y = b/2 through the impact point.
    section = pv.Slice(Input=warp)
    section.SliceType = "Plane"
    section.SliceType.Origin = [0.5 * (bounds[0] + bounds[1]),
                                0.5 * (bounds[2] + bounds[3]),
                                0.5 * (bounds[4] + bounds[5])]
    section.SliceType.Normal = [0, 1, 0]
    pv.Hide(warp, view)
    section_display = pv.Show(section, view)
    field = "von_mises_MPa" if "von_mises_MPa" in fields else "displacement_m"
    colour(section_display, field, "von Mises stress (MPa)"
           if field == "von_mises_MPa" else "displacement (m)",
           "section.png", plate, times, t_show)
    # Zoomed on the impact point: a window of 3 thicknesses each side.
    thickness = bounds[5] - bounds[4]
    focus = [section.SliceType.Origin[0], section.SliceType.Origin[1],
             section.SliceType.Origin[2]]
    view.CameraPosition = [focus[0], bounds[2] - 2 * length, focus[2]]
    view.CameraFocalPoint = focus
    view.CameraViewUp = [0, 0, 1]
    view.CameraParallelProjection = 1
    view.CameraParallelScale = 1.2 * thickness
    set_title("Section y = b/2 through the impact point (displacement x %.0f)"
              % factor, t_show)
    save("section.png")
    pv.Hide(section, view)
    contact_scale_sections(section.SliceType.Origin, bounds[5])
    view.CameraParallelProjection = 0

    # The contact pressure, seen from above.
    if os.path.isfile(os.path.join(directory, "contact.pvd")):
        nodes = pv.PVDReader(FileName=os.path.join(directory, "contact.pvd"))
        if ball_display is not None:
            pv.Hide(ball, view)
        # A map on the top face, not a point cloud: the nodes' pressure
        # interpolated on their Delaunay triangulation (in the plane they
        # lie in, the undeformed top face), isobars at a quarter, half and
        # three quarters of the run's largest pressure, the nodes as dots.
        surface = pv.Delaunay2D(Input=nodes)
        surface_display = pv.Show(surface, view)
        colour(surface_display, "contact_pressure_MPa",
               "contact pressure (MPa)", "contact_pressure.png", nodes,
               pvd_times(os.path.join(directory, "contact.pvd")), t_show)
        peak = rows[-1][4]  # the colour range's top: the run's largest
        isobars = pv.Contour(Input=surface,
                             ContourBy=["POINTS", "contact_pressure_MPa"],
                             Isosurfaces=[f * peak for f in (0.25, 0.5, 0.75)])
        isobar_display = pv.Show(isobars, view)
        isobar_display.ColorArrayName = [None, ""]
        isobar_display.AmbientColor = isobar_display.DiffuseColor = [0, 0, 0]
        isobar_display.LineWidth = 1.5
        node_display = pv.Show(nodes, view)
        node_display.SetRepresentationType("Points")
        node_display.ColorArrayName = [None, ""]
        node_display.AmbientColor = node_display.DiffuseColor = [0.3, 0.3, 0.3]
        node_display.PointSize = 2
        nodes.UpdatePipeline(t_show)
        nb = nodes.GetDataInformation().GetBounds()
        centre = [0.5 * (nb[0] + nb[1]), 0.5 * (nb[2] + nb[3]), nb[5]]
        view.CameraPosition = [centre[0], centre[1], centre[2] + length]
        view.CameraFocalPoint = centre
        view.CameraViewUp = [0, 1, 0]
        view.ResetCamera(False)
        set_title("Contact pressure on the top face (nodes as dots; isobars "
                  "at 25, 50, 75 %% of %.0f MPa)" % peak, t_show)
        save("contact_pressure.png")
        for source in (nodes, surface, isobars):
            pv.Hide(source, view)
        if ball_display is not None:
            pv.Show(ball, view)

    # The animation and the state file: the deformed plate and ball.
    pv.Show(warp, view)
    scene_field = ("von_mises_MPa" if "von_mises_MPa" in fields
                   else "displacement_m")
    scene_label = ("von Mises stress (MPa)" if "von_mises_MPa" in fields
                   else "displacement (m)")
    colour(plate_display, scene_field, scene_label,
           "scene.pvsm and animation", plate, times, t_show)
    camera_3d()
    place_ball(t_show)
    scene_view = {
        "factor": factor, "size": args.size, "field": scene_field,
        "label": scene_label, "low": rows[-1][3], "high": rows[-1][4],
        "preset": "Viridis (matplotlib)", "time": t_show,
        "ball_translate": (list(ball.Transform.Translate)
                           if ball is not None and not resolved and top
                           else None),
        "title": "Deformed plate (displacement x %.0f)%s\n(%s)"
                 % (factor, ball_note, scene),
        "camera": (list(view.CameraPosition), list(view.CameraFocalPoint),
                   list(view.CameraViewUp), view.CameraParallelScale)}

    # The animation: frames over the run, the colour range fixed, one per
    # distinct snapshot time (more frames than snapshots would repeat them).
    if args.frames > 0:
        os.makedirs(os.path.join(out, "animation"), exist_ok=True)
        frames = []
        for t in frame_times(times, args.frames):
            view.ViewTime = t
            place_ball(t)
            set_title("Deformed plate (displacement x %.0f)%s" %
                      (factor, ball_note), t)
            frames.append(save(os.path.join("animation",
                                            "frame_%04d.png" % len(frames))))
        written.append(write_movie(frames, out))
    with open(os.path.join(out, "colours.csv"), "w") as f:
        f.write("picture,field,map,low,high,shown_min,shown_max\n")
        for row in rows:
            f.write("%s,%s,%s,%.9g,%.9g,%.9g,%.9g\n" % row)
    # Last: it starts a new ParaView session.
    written.append(save_state(os.path.join(out, "scene.pvsm"), directory,
                              scene_view))
    for path in written:
        print(path)


if __name__ == "__main__":
    main()
