# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""The readers of the Python plugin (plugin/NarrowVolumePythonPlugin.py): the
clouds ParaView lacks, each as a vtkPolyData with one vertex cell per point,
registered for File > Open under the compiled plugin's proxy names, so that
scripts read files the same way with either plugin:

- PointCloudTextReader: .xyz, .txt and .csv text (x y z in the first three
  columns; header lines and # or // comments skipped), as the pip package's
  command line reads them (narrowvolume._core.read_text_cloud);
- PCDPointCloudReader: PCL's .pcd, ascii, binary and binary_compressed, with
  the compiled reader's parser (narrowvolume._core.read_pcd, which the pip
  package's command line reads with too): x y z, and the other fields as
  point arrays ("rgb" / "rgba" as the colours "Colors");
- LASPointCloudReader: .las, LAS 1.0-1.4 in point formats 0-10, with the
  compiled reader's parser (narrowvolume._core.read_las, which the pip
  package's command line reads with too) and its arrays;
- LAZ and E57 through laspy and pye57 (_scanreaders.py, the compiled
  plugin's Python readers, NarrowVolumeScanReaders.py). Without the module
  a file needs, reading it ends in an error with the pip command that
  installs it.
"""
from paraview.util.vtkAlgorithm import smdomain, smhint, smproperty, smproxy

from . import _core
from ._scanreaders import (E57PointCloudReader, LAZPointCloudReader, ScanFileReader,  # noqa: F401 (proxies)
                           point_cloud)


def read_text(filename):
    """A .xyz / .txt / .csv text cloud, as the pip package's command line
    reads it; ValueError names the line that is not a point."""
    return point_cloud(_core.read_text_cloud(filename), {})


def read_pcd(filename):
    """A .pcd file as a vtkPolyData: x y z, and the other fields as arrays;
    ValueError says why the file cannot be read."""
    return point_cloud(*_core.read_pcd(filename))


def read_las(filename):
    """A .las file as a vtkPolyData with the arrays of the compiled reader;
    ValueError says why the file cannot be read."""
    return point_cloud(*_core.read_las(filename))


# The compiled plugin's text reader is ASCIIPointCloudReader, a name that
# ParaView's reader factory tries before its CSV and PLOT3D readers, since
# its CanReadFile accepts only files of numbers (Plugin/NarrowVolumeReaders.xml).
# A Python reader cannot answer CanReadFile, so this one keeps the name that
# comes after them: OpenDataFile leaves .xyz, .txt and .csv to ParaView's readers.
@smproxy.reader(name="PointCloudTextReader", label="Point Cloud Text Reader",
                extensions=["xyz", "txt", "csv"], file_description="Point Cloud Text Files (x y z)")
class PointCloudTextReader(ScanFileReader):
    """Reads .xyz / .txt / .csv text clouds: x y z in the first three columns."""

    @staticmethod
    def read(filename):
        return read_text(filename)

    @smproperty.stringvector(name="FileName", panel_visibility="never")
    @smdomain.filelist()
    @smhint.filechooser(extensions=["xyz", "txt", "csv"], file_description="Point Cloud Text Files")
    def SetFileName(self, name):
        self.set_file_name(name)


@smproxy.reader(name="PCDPointCloudReader", label="PCD Point Cloud Reader",
                extensions="pcd", file_description="PCD Point Clouds (PCL)")
class PCDPointCloudReader(ScanFileReader):
    """Reads PCL's .pcd files (ascii, binary, binary_compressed)."""

    @staticmethod
    def read(filename):
        return read_pcd(filename)

    @smproperty.stringvector(name="FileName", panel_visibility="never")
    @smdomain.filelist()
    @smhint.filechooser(extensions="pcd", file_description="PCD Point Clouds")
    def SetFileName(self, name):
        self.set_file_name(name)


@smproxy.reader(name="LASPointCloudReader", label="LAS Point Cloud Reader",
                extensions="las", file_description="LAS Point Clouds (LiDAR)")
class LASPointCloudReader(ScanFileReader):
    """Reads uncompressed LAS 1.0-1.4 files, point formats 0-10, with the arrays of the compiled reader."""

    @staticmethod
    def read(filename):
        return read_las(filename)

    @smproperty.stringvector(name="FileName", panel_visibility="never")
    @smdomain.filelist()
    @smhint.filechooser(extensions="las", file_description="LAS Point Clouds")
    def SetFileName(self, name):
        self.set_file_name(name)


__all__ = ["PointCloudTextReader", "PCDPointCloudReader", "LASPointCloudReader", "LAZPointCloudReader",
           "E57PointCloudReader", "read_las", "read_pcd", "read_text"]
