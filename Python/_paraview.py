# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""The proxies of the Python plugin (NarrowVolumePythonPlugin.py): the
wheel's filter as ParaView's NarrowVolumeReconstruction, with the compiled
plugin's proxy (_servermanager.py: the same name, label, menu, properties,
defaults, domains, groups and documentation, and the outputs Volume and
Surface).

ParaView finds a Python plugin's proxies by their _pvsm_proxy_xml, the
ServerManagerConfiguration that paraview.util.vtkAlgorithm's decorators
write on a class; here it is written whole, by the function that writes the
compiled plugin's.

One process computes: under pvbatch or pvserver with several ranks, each
rank asks its source for the whole cloud, the first rank runs the filter
and the others give empty pieces, so that the pieces hold the result of one
rank (the compiled plugin distributes the work instead). A source that
gives each rank a cloud of its own whatever it is asked (the ranks' inputs
differ) would make that result depend on the ranks: then every rank refuses
with an error that names the compiled plugin.
"""
from vtkmodules.vtkCommonCore import vtkDoubleArray
from vtkmodules.vtkCommonDataModel import vtkImageData, vtkPointSet, vtkPolyData
from vtkmodules.vtkParallelCore import vtkCommunicator, vtkMultiProcessController

from . import _properties, _servermanager
from ._filter import vtkNarrowVolumeReconstruction

MPI_ERROR = ("The processes' inputs differ (from %d to %d points): the Python plugin runs on one process and "
             "needs every process to hold the whole cloud. For a distributed run under MPI (pvbatch, pvserver "
             "with several ranks) load the compiled plugin (NarrowVolume, built with ParaView's SDK; see the "
             "README), which spreads the work over the ranks.")


def _input_range(count):
    """(fewest, most) input points over the processes: collective."""
    controller = vtkMultiProcessController.GetGlobalController()
    if controller is None or controller.GetNumberOfProcesses() < 2:
        return count, count
    mine, every = vtkDoubleArray(), vtkDoubleArray()
    mine.SetNumberOfTuples(2)
    mine.SetValue(0, -count)
    mine.SetValue(1, count)
    every.SetNumberOfTuples(2)
    controller.AllReduce(mine, every, vtkCommunicator.MAX_OP)
    return int(-every.GetValue(0)), int(every.GetValue(1))


class NarrowVolumeReconstruction(vtkNarrowVolumeReconstruction):
    """vtkNarrowVolumeReconstruction of the wheel, as ParaView's proxy NarrowVolumeReconstruction."""

    def RequestData(self, request, inInfoVec, outInfoVec):
        """The wheel's filter's run, once every process has the same input."""
        data = vtkPointSet.GetData(inInfoVec[0], 0)
        fewest, most = _input_range(data.GetNumberOfPoints() if data is not None else 0)
        if fewest != most:
            vtkImageData.GetData(outInfoVec, 0).Initialize()
            vtkPolyData.GetData(outInfoVec, 1).Initialize()
            self._error(MPI_ERROR % (fewest, most))
            return 1
        return vtkNarrowVolumeReconstruction.RequestData(self, request, inInfoVec, outInfoVec)


NarrowVolumeReconstruction._pvsm_proxy_xml = _servermanager.proxy_xml(
    _properties, python_class="%s.%s" % (__name__, NarrowVolumeReconstruction.__name__))
