# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""The ParaView plugin in pvpython: LoadPlugin, then NarrowVolumeReconstruction.

    pvpython -m pytest test_plugin_pvpython.py --plugin PLUGIN
"""
import os

import numpy as np
import pytest
from paraview import servermanager
from vtkmodules.util.numpy_support import vtk_to_numpy

import nvclouds
import nvtesting


@pytest.fixture(scope="module")
def sphere(pvs):
    source = pvs.Sphere(Radius=0.5, ThetaResolution=80, PhiResolution=80)
    source.UpdatePipeline()  # as Apply does in the GUI: the offset slider then follows the input's size
    return source


def test_label_and_defaults(pvs, sphere):
    f = pvs.NarrowVolumeReconstruction(Input=sphere)
    assert f.GetXMLLabel() == "Narrow Volume Reconstruction", "label %s" % f.GetXMLLabel()
    defaults = dict(MaximumNumberOfIterations=3, OffsetDistance=0.0, SampleSpacing=0.0, MaximumDimension=0,
                    XiCells=2.0, EpsilonCells=6.0, TimeStep=0.0, ConvergenceTolerance=0.0, GaussSeidelTolerance=1e-6,
                    PreserveOffset=0)
    for name, value in defaults.items():
        assert abs(f.GetPropertyValue(name) - value) < 1e-12, "default %s = %s" % (name, f.GetPropertyValue(name))
    assert f.Domain == "Narrow Band", "Domain default %s" % f.Domain


def test_properties_under_their_xml_names(pvs, sphere):
    """Every property of the XML is reachable in pvpython under its XML name."""
    f = pvs.NarrowVolumeReconstruction(Input=sphere)
    for name in f.ListProperties():
        assert f.GetProperty(name) is not None, "property %s" % name
    for name in ("OffsetDistance", "SampleSpacing", "MaximumDimension", "XiCells", "EpsilonCells", "TimeStep",
                 "MaximumNumberOfIterations", "ConvergenceTolerance", "Domain", "EdgeStoppingFunction",
                 "GaussSeidelTolerance", "RemoveSmallPieces", "PreserveOffset", "OutputVolume", "OutputInitialPhi",
                 "OutputDistance", "OutputNarrowBand"):
        assert name in f.ListProperties(), "pvpython name %s" % name


@pytest.fixture(scope="module")
def shell(pvs, sphere):
    f = pvs.NarrowVolumeReconstruction(Input=sphere)
    f.OffsetDistance = 0.1
    f.SampleSpacing = 0.025
    f.UpdatePipeline()
    return f


def test_outputs(shell):
    volume = servermanager.Fetch(shell)
    surface = servermanager.Fetch(shell, idx=1)
    assert volume.IsA("vtkImageData"), "port 0 is image data: %s" % volume.GetClassName()
    assert surface.IsA("vtkPolyData"), "port 1 is polydata: %s" % surface.GetClassName()
    phi = vtk_to_numpy(volume.GetPointData().GetArray("phi"))
    assert phi.min() >= -1 and phi.max() <= 1, "phi in [-1, 1]"
    assert nvtesting.boundary_edges(surface) == 0, "closed surface"
    assert nvtesting.regions(surface) == 2, "two sheets"
    r = np.linalg.norm(nvtesting.points_of(surface), axis=1)
    assert abs(r[r < 0.5].mean() - 0.4) < 0.0125 and abs(r[r > 0.5].mean() - 0.6) < 0.0125, "sheet radii"


def test_enumerations_by_name(shell):
    """Enumerations by name, as a pvpython user writes them."""
    shell.Domain = "Whole Domain"
    shell.EdgeStoppingFunction = "Eq. (3): 1-phi0^2"
    shell.UpdatePipeline()
    assert servermanager.Fetch(shell, idx=1).GetNumberOfPoints() > 0, "whole domain, eq. 3"


# Plain-text clouds open through the plugin's reader and go straight into the filter.
@pytest.fixture(scope="module")
def balls():
    """ball.pts and ball.xyz: 500 points of a sphere."""
    folder = nvtesting.scratch_folder(prefix="nv-pv-")
    for name in ("ball.pts", "ball.xyz"):
        with open(os.path.join(folder, name), "w") as f:
            f.write("\n".join("%.6f %.6f %.6f" % tuple(p) for p in nvclouds.sphere_points(500, 0.5)))
    return folder


@pytest.fixture(scope="module")
def pts_reader(pvs, balls):
    """.pts opens with ParaView's own PTSReader."""
    return pvs.OpenDataFile(os.path.join(balls, "ball.pts"))


@pytest.fixture(scope="module")
def xyz_reader(pvs, balls):
    """.xyz is also claimed by ParaView's PLOT3D and molecular XYZ readers,
    and OpenDataFile takes the first of them (ParaView 5.11 consults the
    default-reader setting the plugin adds only in the GUI's File > Open, see
    GUIOpenFiles), so scripts name ours."""
    reader = pvs.PointCloudTextReader(FileName=os.path.join(balls, "ball.xyz"))
    reader.UpdatePipeline()
    return reader


def test_pts_opens_with_paraviews_reader(pts_reader):
    assert pts_reader is not None and pts_reader.GetXMLName() == "PTSReader", "pts opens with ParaView's reader"


def test_xyz_read_by_name(xyz_reader):
    assert xyz_reader.GetDataInformation().GetNumberOfPoints() == 500, "xyz read by name"


def test_shell_from_a_pts_file(pvs, pts_reader):
    pts_reader.UpdatePipeline()
    shell = pvs.NarrowVolumeReconstruction(Input=pts_reader, SampleSpacing=0.02, OffsetDistance=0.08, Sheets="Outer")
    shell.UpdatePipeline()
    assert shell.GetDataInformation(1).GetNumberOfCells() > 100, "shell from a pts file"


def test_shell_from_an_xyz_file(pvs, xyz_reader):
    from_xyz = pvs.NarrowVolumeReconstruction(Input=xyz_reader, SampleSpacing=0.02, OffsetDistance=0.08)
    from_xyz.UpdatePipeline()
    assert from_xyz.GetDataInformation(1).GetNumberOfCells() > 100, "shell from an xyz file"


def test_scan_surface_by_its_label(pvs, pts_reader):
    """Sheets = "Scan" (the panel's label) gives one closed surface on the ball, no sheet."""
    scan = pvs.NarrowVolumeReconstruction(Input=pts_reader, SampleSpacing=0.02, OffsetDistance=0.08, Sheets="Scan")
    scan.UpdatePipeline()
    surface = pvs.servermanager.Fetch(scan, idx=1)
    assert surface.GetNumberOfCells() > 100 and nvtesting.boundary_edges(surface) == 0
    assert nvtesting.regions(surface) == 1, "one surface, not two sheets"
    volume = pvs.servermanager.Fetch(scan, idx=0)
    assert volume.GetFieldData().GetArray("ScanSurface").GetValue(0) == 1


def test_offset_default_and_slider(pvs, pts_reader):
    """The offset's default is 0 (automatic); its slider reaches a quarter of the input's largest side."""
    pts_reader.UpdatePipeline()
    fresh = pvs.NarrowVolumeReconstruction(Input=pts_reader)
    slider = fresh.GetProperty("OffsetDistance").SMProperty.GetDomain("bounds")
    assert fresh.OffsetDistance == 0.0 and slider.GetMinimum(0) == 0.0 and abs(slider.GetMaximum(0) - 0.25) < 1e-3, \
        "offset default 0, slider [0, 0.25 x the largest side]: %g, [%g, %g]" % (
            fresh.OffsetDistance, slider.GetMinimum(0), slider.GetMaximum(0))


def test_messages_name_the_panels_labels(pvs, sphere):
    """In ParaView the filter's warnings name the panel's labels (the proxy
    sets PanelLabelsInMessages), and the read-only values show what the run
    chose."""
    from vtkmodules.util.misc import calldata_type
    from vtkmodules.util.vtkConstants import VTK_STRING
    f = pvs.NarrowVolumeReconstruction(Input=sphere, OffsetDistance=0.01, MaximumDimension=40)  # a coarse grid
    texts = []

    @calldata_type(VTK_STRING)
    def on_warning(caller, event, text):
        texts.append(text)

    observer = f.GetClientSideObject().AddObserver("WarningEvent", on_warning)
    f.UpdatePipeline()
    f.GetClientSideObject().RemoveObserver(observer)
    print(texts, f.SampleSpacingUsed, f.GridDimensionsUsed)
    assert any("Sample Spacing" in t and "Maximum Dimension" in t and "SampleSpacing" not in t for t in texts), texts
    assert f.OffsetDistanceUsed == pytest.approx(0.01) and f.SampleSpacingUsed > 0.01 / 3  # coarse, as warned
    assert max(f.GridDimensionsUsed) == 41
    assert f.GridUsed == " x ".join(str(n) for n in f.GridDimensionsUsed)  # the panel's text


def test_a_part_with_drain_hole_positions(pvs, sphere):
    """The printing properties in pvpython: DrainHolePositions as a flat
    list of x y z, one name for the part's size (PartSizeUsed, as in C++
    and Python), and group titles that say what 0 does (Wall Thickness 0 is
    the shell, not "automatic")."""
    f = pvs.NarrowVolumeReconstruction(Input=sphere, OffsetDistance=0.1, SampleSpacing=0.02, WallThickness=0.05)
    f.DrainHolePositions = [0.5, 0.0, 0.0, 0.0, 0.0, -0.5]  # the sphere's +x side and its bottom
    f.UpdatePipeline()
    volume = servermanager.Fetch(f)
    assert volume.GetFieldData().GetArray("DrainHoles").GetValue(0) == 2
    assert f.GetClientSideObject().GetNumberOfDrainHolePositions() == 2
    assert f.PartSizeUsed.endswith(")") and "(the cloud " in f.PartSizeUsed, f.PartSizeUsed
    titles = [f.SMProxy.GetPropertyGroup(g).GetXMLLabel() for g in range(f.SMProxy.GetNumberOfPropertyGroups())]
    assert "Printing (a part when Wall Thickness > 0)" in titles and "Grid (0 = automatic)" in titles, titles


@pytest.mark.parametrize("text,says", [("", "the file is empty"), ("hello world\nfoo bar\n", "no line of x y z numbers"),
                                       ("3\nwater\nO 0 0 0\nH 0.75 0.58 0\n", "molecular XYZ file")])
def test_opening_a_text_xyz_that_is_no_cloud(pvs, tmp_path, text, says):
    """OpenDataFile on an empty, a worded or a molecular .xyz: the plugin's
    reader, and its message (ParaView's PLOT3D reader, which took them
    before, crashed pvpython)."""
    from vtkmodules.util.misc import calldata_type
    from vtkmodules.util.vtkConstants import VTK_STRING
    path = tmp_path / "not-a-cloud.xyz"
    path.write_text(text)
    reader = pvs.OpenDataFile(str(path))
    assert reader.GetXMLName() == "ASCIIPointCloudReader", reader.GetXMLName()
    texts = []

    @calldata_type(VTK_STRING)
    def on_error(caller, event, message):
        texts.append(message)

    reader.GetClientSideObject().AddObserver("ErrorEvent", on_error)
    reader.UpdatePipeline()
    assert any(says in t for t in texts), texts
    assert reader.GetDataInformation().GetNumberOfPoints() == 0


def test_wall_thickness_slider_and_reset(pvs, sphere):
    """The Wall Thickness slider reaches 5 % of the cloud's longest side
    (past the how-to's 2 % of the diagonal on any cloud), and its reset
    button gives 0, the shell, as the how-to says."""
    f = pvs.NarrowVolumeReconstruction(Input=sphere, WallThickness=0.03)
    prop = f.GetProperty("WallThickness").SMProperty
    domain = prop.GetDomain("bounds")
    domain.Update(None)
    bounds = sphere.GetDataInformation().GetBounds()
    longest = max(bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4])
    diagonal = (sum((bounds[2 * a + 1] - bounds[2 * a]) ** 2 for a in range(3))) ** 0.5
    assert domain.GetMaximum(0) == pytest.approx(0.05 * longest) and domain.GetMaximum(0) > 0.02 * diagonal
    prop.ResetToDomainDefaults()
    assert f.WallThickness == 0.0
