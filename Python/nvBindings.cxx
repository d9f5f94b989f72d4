// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// narrowvolume._core: the numerical core for Python (nanobind), in the wheel
// that pip builds without VTK. The Python filter (_filter.py) drives a run
// through these names, which are the core's own (nvReconstruction.h,
// nvOutputs.h): nothing of the method is decided here.
//
// The GIL is released while the core computes (Run, FillVolume,
// KeepSheets). The core reports progress and asks whether to stop on the
// calling thread only (nv::CallerMonitor): there the monitor takes the GIL
// back, runs Python's signal handlers (Ctrl-C raises KeyboardInterrupt) and
// calls the Python callbacks. An exception from either stops the run and is
// raised again when the call returns.
#include "nvOutputs.h"
#include "nvParallel.h"
#include "nvReconstruction.h"
#include "nvSheets.h"

#include <nanobind/nanobind.h>
#include <nanobind/ndarray.h>
#include <nanobind/stl/array.h>
#include <nanobind/stl/optional.h>
#include <nanobind/stl/pair.h>
#include <nanobind/stl/shared_ptr.h>
#include <nanobind/stl/string.h>
#include <nanobind/stl/vector.h>

#include <array>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <utility>
#include <vector>

namespace nb = nanobind;
using namespace nb::literals;

namespace
{
using Points = nb::ndarray<const double, nb::shape<-1, 3>, nb::c_contig, nb::device::cpu>;
using FloatArray = nb::ndarray<float, nb::ndim<1>, nb::c_contig, nb::device::cpu>;
using ByteArray = nb::ndarray<unsigned char, nb::ndim<1>, nb::c_contig, nb::device::cpu>;

/// Progress and abort of a run, from and to Python: report(progress) gets the
/// whole run's progress in [0, 1], poll() says whether to stop (both
/// optional), and Ctrl-C stops the run too.
class PythonMonitor : public nv::CallerMonitor
{
public:
  PythonMonitor(nb::object report, nb::object poll)
    : ReportCallback(std::move(report))
    , PollCallback(std::move(poll))
  {
  }

  ~PythonMonitor() override
  {
    nb::gil_scoped_acquire gil;
    this->Pending.reset();
    this->ReportCallback.reset();
    this->PollCallback.reset();
  }

  /// Raises the exception a callback or a signal handler raised, if any.
  void RaisePending()
  {
    if (this->Pending)
    {
      std::unique_ptr<nb::python_error> pending = std::move(this->Pending);
      pending->restore();
      throw nb::python_error();
    }
  }

protected:
  void Report(double progress) override
  {
    nb::gil_scoped_acquire gil;
    if (this->Pending || !this->ReportCallback.is_valid() || this->ReportCallback.is_none())
    {
      return;
    }
    try
    {
      this->ReportCallback(progress);
    }
    catch (nb::python_error& error)
    {
      this->Pending.reset(new nb::python_error(std::move(error)));
    }
  }

  bool Poll() override
  {
    nb::gil_scoped_acquire gil;
    if (this->Pending)
    {
      return true;
    }
    try
    {
      if (PyErr_CheckSignals() != 0) // KeyboardInterrupt, or what a handler raised
      {
        throw nb::python_error();
      }
      if (this->PollCallback.is_valid() && !this->PollCallback.is_none())
      {
        return nb::cast<bool>(this->PollCallback());
      }
    }
    catch (nb::python_error& error)
    {
      this->Pending.reset(new nb::python_error(std::move(error)));
      return true;
    }
    return false;
  }

private:
  nb::object ReportCallback;
  nb::object PollCallback;
  std::unique_ptr<nb::python_error> Pending;
};

/// A run with its monitor (which it keeps alive).
class PythonRun
{
public:
  PythonRun(const nv::Settings& settings, std::shared_ptr<PythonMonitor> monitor)
    : Watch(std::move(monitor))
    , Run(settings, nullptr, this->Watch.get())
  {
  }

  bool Start(Points points)
  {
    std::vector<double> xyz(points.data(), points.data() + 3 * points.shape(0));
    bool ok = false;
    {
      nb::gil_scoped_release release;
      ok = this->Run.Run(std::move(xyz));
    }
    this->RaisePending();
    return ok;
  }

  void Fill(std::optional<FloatArray> phi, std::optional<FloatArray> initialPhi, std::optional<FloatArray> distance,
    std::optional<ByteArray> band, std::int64_t kBegin, std::int64_t kEnd, bool monitored)
  {
    const nv::Grid& grid = this->Run.GetGrid();
    if (kEnd < 0)
    {
      kEnd = this->Run.ComputedEnd();
    }
    if (this->Run.GetPhi().empty() || kBegin < this->Run.ComputedBegin() || kEnd > this->Run.ComputedEnd() ||
      kEnd <= kBegin)
    {
      throw std::invalid_argument("FillVolume: no finished run, or layers outside the computed ones");
    }
    const std::size_t nodes = static_cast<std::size_t>(grid.Dims[0] * grid.Dims[1] * (kEnd - kBegin));
    nv::VolumeArrays arrays;
    auto take = [&](auto& array, auto*& pointer, const char* name) {
      if (array)
      {
        if (array->size() != nodes)
        {
          std::ostringstream error;
          error << "FillVolume: " << name << " holds " << array->size() << " values, not " << nodes;
          throw std::invalid_argument(error.str());
        }
        pointer = array->data();
      }
    };
    take(phi, arrays.Phi, "phi");
    take(initialPhi, arrays.InitialPhi, "initial_phi");
    take(distance, arrays.Distance, "distance");
    take(band, arrays.Band, "band");
    {
      nb::gil_scoped_release release;
      this->Run.FillVolume(arrays, kBegin, kEnd, monitored);
    }
    this->RaisePending();
  }

  void RaisePending()
  {
    if (this->Watch)
    {
      this->Watch->RaisePending();
    }
  }

  std::shared_ptr<PythonMonitor> Watch;
  nv::Reconstruction Run;
};

std::array<double, 6> Bounds(const std::vector<double>& bounds)
{
  if (bounds.size() != 6)
  {
    throw std::invalid_argument("bounds: 6 values (xmin, xmax, ymin, ymax, zmin, zmax)");
  }
  std::array<double, 6> b;
  std::copy(bounds.begin(), bounds.end(), b.begin());
  return b;
}
} // namespace

NB_MODULE(_core, m)
{
  m.doc() = "The numerical core of NarrowVolume (Filters/Core), for the Python filter of the wheel.";
  // A filter alive at exit (a script's global) holds its Settings; VTK's
  // Python objects may outlive nanobind's leak check, which would only warn.
  nb::set_leak_warnings(false);

  nb::enum_<nv::Domain>(m, "Domain", nb::is_arithmetic(), "Which nodes the scheme updates.")
    .value("NarrowBand", nv::Domain::NarrowBand)
    .value("WholeDomain", nv::Domain::WholeDomain);
  nb::enum_<nv::EdgeStopping>(m, "EdgeStopping", nb::is_arithmetic(), "The edge-stopping function g, by equation.")
    .value("Eq3", nv::EdgeStopping::Eq3)
    .value("Eq4", nv::EdgeStopping::Eq4);
  nb::enum_<nv::Sheets>(m, "Sheets", nb::is_arithmetic(), "The phi = 0 sheets a surface keeps.")
    .value("Both", nv::Sheets::Both)
    .value("Outer", nv::Sheets::Outer)
    .value("Inner", nv::Sheets::Inner);

  // Every field of nv::Settings; a default-constructed one holds the defaults.
  nb::class_<nv::Settings>(m, "Settings", "What the user chooses (nv::Settings): the filter's properties.")
    .def(nb::init<>())
    .def_rw("OffsetDistance", &nv::Settings::OffsetDistance)
    .def_rw("SampleSpacing", &nv::Settings::SampleSpacing)
    .def_rw("MaximumDimension", &nv::Settings::MaximumDimension)
    .def_rw("XiCells", &nv::Settings::XiCells)
    .def_rw("EpsilonCells", &nv::Settings::EpsilonCells)
    .def_rw("TimeStep", &nv::Settings::TimeStep)
    .def_rw("MaximumNumberOfIterations", &nv::Settings::MaximumNumberOfIterations)
    .def_rw("ConvergenceTolerance", &nv::Settings::ConvergenceTolerance)
    .def_rw("GaussSeidelTolerance", &nv::Settings::GaussSeidelTolerance)
    .def_rw("Mode", &nv::Settings::Mode)
    .def_rw("EdgeFunction", &nv::Settings::EdgeFunction)
    .def_rw("KeptSheets", &nv::Settings::KeptSheets)
    .def_rw("OutputVolume", &nv::Settings::OutputVolume)
    .def_rw("OutputInitialPhi", &nv::Settings::OutputInitialPhi)
    .def_rw("OutputDistance", &nv::Settings::OutputDistance)
    .def_rw("OutputNarrowBand", &nv::Settings::OutputNarrowBand)
    .def_rw("NumberOfThreads", &nv::Settings::NumberOfThreads)
    .def_rw("MemoryLimit", &nv::Settings::MemoryLimit)
    .def("MemoryLimitBytes", &nv::Settings::MemoryLimitBytes)
    .def("OutputBytesPerNode", &nv::Settings::OutputBytesPerNode);

  nb::class_<nv::Grid>(m, "Grid", "The uniform grid: nodes Origin + (i, j, k) Spacing.")
    .def_prop_ro("Origin", [](const nv::Grid& g) { return g.Origin; })
    .def_prop_ro("Dims", [](const nv::Grid& g) { return g.Dims; })
    .def_ro("Spacing", &nv::Grid::Spacing)
    .def("NumberOfNodes", &nv::Grid::NumberOfNodes);

  nb::class_<nv::Plan>(m, "Plan", "The grid that points with given bounds get (nv::MakePlan).")
    .def_ro("TheGrid", &nv::Plan::TheGrid)
    .def_ro("Error", &nv::Plan::Error)
    .def("Valid", &nv::Plan::Valid);
  m.def(
    "MakePlan",
    [](const nv::Settings& settings, const std::vector<double>& bounds) {
      const std::array<double, 6> b = Bounds(bounds);
      return nv::MakePlan(settings, b.data());
    },
    "settings"_a, "bounds"_a, "The grid for points with these bounds, or why there is none.");

  nb::class_<PythonMonitor>(m, "Monitor",
    "Progress and abort of a run: report(progress) receives the whole run's progress in [0, 1], never "
    "going back; poll() returns True to stop it. Both are called on the thread that made the monitor, "
    "which also handles Ctrl-C there.")
    .def(nb::new_([](nb::object report, nb::object poll) {
      return std::make_shared<PythonMonitor>(std::move(report), std::move(poll));
    }),
      "report"_a = nb::none(), "poll"_a = nb::none())
    .def(
      "Stage",
      [](PythonMonitor& monitor, double begin, double width) {
        monitor.Stage(begin, width);
        monitor.RaisePending();
      },
      "begin"_a, "width"_a, "A stage of the run begins; it covers [begin, begin + width) of its progress.")
    .def(
      "Progress",
      [](PythonMonitor& monitor, double fraction) {
        monitor.Progress(fraction);
        monitor.RaisePending();
      },
      "fraction"_a, "The fraction done of the current stage.")
    .def(
      "Aborted",
      [](PythonMonitor& monitor) {
        const bool stop = monitor.Aborted();
        monitor.RaisePending();
        return stop;
      },
      "Whether the run is to stop.");

  nb::class_<PythonRun>(m, "Reconstruction", "The whole run of the method (nv::Reconstruction), serial.")
    .def(nb::init<const nv::Settings&, std::shared_ptr<PythonMonitor>>(), "settings"_a, "monitor"_a = nb::none())
    .def("Run", &PythonRun::Start, "points"_a,
      "Steps 1-6 for the points ((n, 3) float64, C order), without the GIL. False when the run stops: "
      "Error() says why, or Aborted().")
    .def("Error", [](const PythonRun& r) { return r.Run.Error(); })
    .def("Aborted", [](const PythonRun& r) { return r.Run.Aborted(); })
    .def("GetSettings", [](const PythonRun& r) { return r.Run.GetSettings(); })
    .def("GetGrid", [](const PythonRun& r) { return r.Run.GetGrid(); })
    .def("PieceBegin", [](const PythonRun& r) { return r.Run.PieceBegin(); })
    .def("PieceEnd", [](const PythonRun& r) { return r.Run.PieceEnd(); })
    .def("NumberOfBandNodes", [](const PythonRun& r) { return r.Run.NumberOfBandNodes(); })
    .def("RelativeChanges", [](const PythonRun& r) { return r.Run.RelativeChanges(); })
    .def("SetupSeconds", [](const PythonRun& r) { return r.Run.SetupSeconds(); })
    .def("EvolutionSeconds", [](const PythonRun& r) { return r.Run.EvolutionSeconds(); })
    .def("FillVolume", &PythonRun::Fill, "phi"_a = nb::none(), "initial_phi"_a = nb::none(),
      "distance"_a = nb::none(), "band"_a = nb::none(), "k_begin"_a = 0, "k_end"_a = -1, "monitored"_a = true,
      "Step 7: fills the given arrays (float32; band uint8), Nx Ny (k_end - k_begin) values each, of the "
      "node layers [k_begin, k_end), without the GIL.")
    .def(
      "SurfaceSlabs",
      [](const PythonRun& r, std::int64_t kFirst, std::int64_t kLast) {
        std::vector<std::pair<std::int64_t, std::int64_t>> slabs;
        for (const nv::Slab& slab : nv::SurfaceSlabs(r.Run.GetDistance(), r.Run.GetBand(), kFirst, kLast))
        {
          slabs.emplace_back(slab.Begin, slab.End);
        }
        return slabs;
      },
      "k_first"_a = 0, "k_last"_a = -1, "The (begin, end) node layers of the slabs that hold band nodes.");

  m.def(
    "KeepSheets",
    [](const nv::Grid& grid, FloatArray phi, nv::Sheets which) {
      if (static_cast<std::int64_t>(phi.size()) != grid.NumberOfNodes())
      {
        throw std::invalid_argument("KeepSheets: phi must hold one value per grid node");
      }
      nb::gil_scoped_release release;
      return nv::KeepSheets(grid, phi.data(), which);
    },
    "grid"_a, "phi"_a, "which"_a,
    "Rewrites phi so that its zero set holds only the chosen sheets; returns the number of cavity nodes.");

  m.def("SurfaceBySlabs", &nv::SurfaceBySlabs, "settings"_a, "distributed"_a = false);
  m.def("NoInnerSheet", &nv::NoInnerSheet, "settings"_a, "cavities"_a);
  m.def("EmptySurfaceWarning", &nv::EmptySurfaceWarning, "settings"_a, "spacing"_a);
  m.def("NoInnerSheetWarning", &nv::NoInnerSheetWarning);
  m.def("OneSheetNeedsGridWarning", &nv::OneSheetNeedsGridWarning);
  m.attr("VolumeStage") = nb::make_tuple(nv::VolumeStage[0], nv::VolumeStage[1]);
  m.attr("SurfaceStage") = nb::make_tuple(nv::SurfaceStage[0], nv::SurfaceStage[1]);
  m.attr("SlabStage") = nb::make_tuple(nv::SlabStage[0], nv::SlabStage[1]);
  m.attr("SlabCells") = nv::SlabCells;
}
