// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// narrowvolume._core: the numerical core for Python (nanobind), in the wheel
// that pip builds without VTK. The Python filter (_filter.py) drives a run
// through these names, which are the core's own (nvReconstruction.h,
// nvReconstruct.h, nvSampling.h): nothing of the method is decided here. It
// also holds the readers' PLY check (nvPLY.h), for the command line, and
// their PCD and text parsers (nvReaderBindings.cxx).
//
// The GIL is released while the core computes (Sampling.Measure,
// Reconstruction.Reconstruct: nv::Reconstruct, the run and its outputs). The core reports progress and asks
// whether to stop on the calling thread only (nv::CallerMonitor): there the
// monitor takes the GIL back, runs Python's signal handlers (Ctrl-C raises
// KeyboardInterrupt) and calls the Python callbacks. An exception from
// either stops the run and is raised again when the call returns.
//
// The arrays the core fills (the dense volume, the surface) are allocated
// here and handed to numpy without a copy; the Python filter hands them to
// VTK without a copy either.
#include "nvReconstruct.h"
#include "nvPLY.h"
#include "nvParallel.h"
#include "nvReconstruction.h"
#include "nvSampling.h"
#include "nvSurface.h"

#include <nanobind/nanobind.h>
#include <nanobind/ndarray.h>
#include <nanobind/stl/array.h>
#include <nanobind/stl/pair.h>
#include <nanobind/stl/shared_ptr.h>
#include <nanobind/stl/string.h>
#include <nanobind/stl/tuple.h>
#include <nanobind/stl/vector.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <memory>
#include <new>
#include <stdexcept>
#include <utility>
#include <vector>

namespace nb = nanobind;
using namespace nb::literals;

namespace
{
using Points = nb::ndarray<const double, nb::shape<-1, 3>, nb::c_contig, nb::device::cpu>;
using FloatArray = nb::ndarray<float, nb::ndim<1>, nb::c_contig, nb::device::cpu>;

/// Memory from malloc that grows in place (realloc) and is handed to numpy
/// at the end. It starts at 64 MiB of address space: the system maps pages
/// only when they are written, and malloc serves such a size by mmap, so
/// growing and the final trim are mremap calls, without copies or freed
/// pieces left in the heap (the surface is held once, as in the C++ filter).
template <class T>
class Buffer
{
public:
  Buffer() = default;
  Buffer(const Buffer&) = delete;
  Buffer& operator=(const Buffer&) = delete;
  ~Buffer() { std::free(this->Data); }

  /// Room for n more values at the end.
  T* Extend(std::size_t n)
  {
    if (this->Size + n > this->Capacity)
    {
      const std::size_t start = (std::size_t(1) << 26) / sizeof(T);
      this->Reallocate(std::max({ this->Size + n, 2 * this->Capacity, start }));
    }
    T* room = this->Data + this->Size;
    this->Size += n;
    return room;
  }
  T* Get() { return this->Data; }
  std::size_t GetSize() const { return this->Size; }
  void Truncate(std::size_t size) { this->Size = std::min(size, this->Size); }

  /// The values as a numpy array of `columns` columns, which owns them; the buffer is empty afterwards.
  nb::object Release(std::size_t columns)
  {
    this->Reallocate(std::max<std::size_t>(this->Size, 1));
    T* data = this->Data;
    nb::capsule owner(data, [](void* p) noexcept { std::free(p); });
    const std::size_t shape[2] = { this->Size / columns, columns };
    this->Data = nullptr;
    this->Size = this->Capacity = 0;
    return nb::cast(nb::ndarray<nb::numpy, T>(data, columns > 1 ? 2 : 1, shape, owner));
  }

private:
  void Reallocate(std::size_t capacity)
  {
    T* data = static_cast<T*>(std::realloc(this->Data, capacity * sizeof(T)));
    if (!data)
    {
      throw std::bad_alloc();
    }
    this->Data = data;
    this->Capacity = capacity;
  }

  T* Data = nullptr;
  std::size_t Size = 0;
  std::size_t Capacity = 0;
};

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

/// A surface received from the core into growing buffers.
class MeshSink : public nv::SurfaceSink
{
public:
  void AddPoints(std::int64_t n, double*& xyz, float*& normals) override
  {
    xyz = this->Points.Extend(static_cast<std::size_t>(3 * n));
    normals = this->Normals.Extend(static_cast<std::size_t>(3 * n));
  }
  nv::VertexId* AddTriangles(std::int64_t n) override
  {
    return this->Triangles.Extend(static_cast<std::size_t>(3 * n));
  }
  nv::SurfaceArrays View() override
  {
    nv::SurfaceArrays arrays;
    arrays.Points = this->Points.Get();
    arrays.Normals = this->Normals.Get();
    arrays.Triangles = this->Triangles.Get();
    arrays.NumberOfPoints = static_cast<std::int64_t>(this->Points.GetSize() / 3);
    arrays.NumberOfTriangles = static_cast<std::int64_t>(this->Triangles.GetSize() / 3);
    return arrays;
  }
  void Truncate(const nv::SurfaceArrays& arrays) override
  {
    this->Points.Truncate(static_cast<std::size_t>(3 * arrays.NumberOfPoints));
    this->Normals.Truncate(static_cast<std::size_t>(3 * arrays.NumberOfPoints));
    this->Triangles.Truncate(static_cast<std::size_t>(3 * arrays.NumberOfTriangles));
  }

  Buffer<double> Points;
  Buffer<float> Normals;
  Buffer<nv::VertexId> Triangles;
};

/// The dense arrays a run fills (phi, and those the settings ask for),
/// allocated when the run asks.
struct VolumeBuffers
{
  nv::VolumeContents Contents;
  Buffer<float> PhiValues, InitialPhiValues, DistanceValues;
  Buffer<unsigned char> BandValues;

  nv::VolumeArrays Allocate(std::size_t nodes)
  {
    nv::VolumeArrays arrays;
    arrays.Phi = this->PhiValues.Extend(nodes);
    arrays.InitialPhi = this->Contents.InitialPhi ? this->InitialPhiValues.Extend(nodes) : nullptr;
    arrays.Distance = this->Contents.Distance ? this->DistanceValues.Extend(nodes) : nullptr;
    arrays.Band = this->Contents.Band ? this->BandValues.Extend(nodes) : nullptr;
    return arrays;
  }
};

/// A run with its monitor (which it keeps alive) and the arrays it fills.
class PythonRun
{
public:
  PythonRun(const nv::Settings& settings, std::shared_ptr<PythonMonitor> monitor, bool hostLauncher)
    : Watch(std::move(monitor))
    , Run(settings, nullptr, this->Watch.get(), hostLauncher ? nv::GpuKernels::OnHost : nv::GpuKernels::OnGpu)
  {
  }

  /// The whole run and its outputs (nv::Reconstruct), without the GIL: the
  /// surface into the sink, the dense arrays for TakeVolume.
  nv::Outcome Reconstruct(Points points, std::shared_ptr<const nv::Sampling> sampling, MeshSink& sink)
  {
    std::vector<double> xyz(points.data(), points.data() + 3 * points.shape(0));
    nv::VolumeRequest request;
    request.Allocate = [this](std::int64_t kBegin, std::int64_t kEnd) {
      const nv::Grid& grid = this->Run.GetGrid();
      this->Volume.reset(new VolumeBuffers);
      this->Volume->Contents = nv::DenseArraysAsked(this->Run.GetSettings());
      return this->Volume->Allocate(static_cast<std::size_t>(grid.Dims[0] * grid.Dims[1] * (kEnd - kBegin)));
    };
    nv::Outcome outcome;
    {
      nb::gil_scoped_release release;
      outcome = nv::Reconstruct(this->Run, std::move(xyz), std::move(sampling), sink, request, false);
    }
    this->RaisePending();
    return outcome;
  }

  /// {name: numpy array} of the filled dense arrays (once).
  nb::dict TakeVolume()
  {
    nb::dict arrays;
    if (this->Volume)
    {
      arrays["phi"] = this->Volume->PhiValues.Release(1);
      if (this->Volume->Contents.InitialPhi)
      {
        arrays["InitialPhi"] = this->Volume->InitialPhiValues.Release(1);
      }
      if (this->Volume->Contents.Distance)
      {
        arrays["Distance"] = this->Volume->DistanceValues.Release(1);
      }
      if (this->Volume->Contents.Band)
      {
        arrays["NarrowBand"] = this->Volume->BandValues.Release(1);
      }
      this->Volume.reset();
    }
    return arrays;
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
  std::unique_ptr<VolumeBuffers> Volume;
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

// The readers' parsers (nvReaderBindings.cxx).
void BindReaders(nb::module_& m);

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
  nb::enum_<nv::ComputeDevice>(m, "ComputeDevice", nb::is_arithmetic(), "Where the evolution runs.")
    .value("Automatic", nv::ComputeDevice::Automatic)
    .value("CPU", nv::ComputeDevice::CPU)
    .value("GPU", nv::ComputeDevice::GPU);
  nb::enum_<nv::Sheets>(m, "Sheets", nb::is_arithmetic(), "The phi = 0 sheets a surface keeps.")
    .value("Both", nv::Sheets::Both)
    .value("Outer", nv::Sheets::Outer)
    .value("Inner", nv::Sheets::Inner)
    .value("Scan", nv::Sheets::Scan);
  nb::enum_<nv::DrainAxis>(m, "DrainAxis", nb::is_arithmetic(), "The way down for the drain holes.")
    .value("MinusX", nv::DrainAxis::MinusX)
    .value("PlusX", nv::DrainAxis::PlusX)
    .value("MinusY", nv::DrainAxis::MinusY)
    .value("PlusY", nv::DrainAxis::PlusY)
    .value("MinusZ", nv::DrainAxis::MinusZ)
    .value("PlusZ", nv::DrainAxis::PlusZ);

  // Every field of nv::Settings (the property table's, NV_SETTINGS); a
  // default-constructed one holds the defaults.
  nb::class_<nv::Settings> settings(m, "Settings", "What the user chooses (nv::Settings): the filter's properties.");
  settings.def(nb::init<>())
    .def("MemoryLimitBytes", &nv::Settings::MemoryLimitBytes)
    .def("OutputBytesPerNode", &nv::Settings::OutputBytesPerNode);
#define NV_BIND(Type, Name, Default) settings.def_rw(#Name, &nv::Settings::Name);
  NV_SETTINGS(NV_BIND)
  // The list properties (_properties.py's LIST_PROPERTIES): x y z after one another.
  settings.def_rw("DrainHolePositions", &nv::Settings::DrainHolePositions);
#undef NV_BIND

  nb::class_<nv::Grid>(m, "Grid", "The uniform grid: nodes Origin + (i, j, k) Spacing.")
    .def_prop_ro("Origin", [](const nv::Grid& g) { return g.Origin; })
    .def_prop_ro("Dims", [](const nv::Grid& g) { return g.Dims; })
    .def_ro("Spacing", &nv::Grid::Spacing)
    .def("NumberOfNodes", &nv::Grid::NumberOfNodes);
  nb::class_<nv::Parameters>(m, "Parameters", "The scheme's parameters on the grid (nv::Parameters).")
    .def_ro("OffsetDistance", &nv::Parameters::OffsetDistance)
    .def_ro("Spacing", &nv::Parameters::Spacing);
  nb::class_<nv::Plan>(m, "Plan", "The grid that points with given bounds get (nv::MakePlan).")
    .def_ro("TheGrid", &nv::Plan::TheGrid)
    .def_ro("Scheme", &nv::Plan::Scheme)
    .def_ro("ClosingRadius", &nv::Plan::ClosingRadius)
    .def_ro("Error", &nv::Plan::Error)
    .def("Valid", &nv::Plan::Valid);

  nb::class_<nv::SamplingStatistics>(m, "SamplingStatistics", "Nearest-neighbour distances of a cloud.")
    .def_ro("Points", &nv::SamplingStatistics::Points)
    .def_ro("MedianSpacing", &nv::SamplingStatistics::MedianSpacing)
    .def_ro("WideSpacing", &nv::SamplingStatistics::WideSpacing)
    .def("Valid", &nv::SamplingStatistics::Valid);
  nb::class_<nv::Sampling>(m, "Sampling", "The sampling of a cloud (nv::Sampling), measured once per cloud.")
    .def_static(
      "Measure",
      [](Points points, int threads, std::shared_ptr<PythonMonitor> monitor) -> std::shared_ptr<nv::Sampling> {
        auto sampling = std::make_shared<nv::Sampling>();
        std::vector<double> xyz(points.data(), points.data() + 3 * points.shape(0));
        bool measured = false;
        {
          nb::gil_scoped_release release;
          nv::WithThreads(threads, [&]() { measured = sampling->Measure(xyz, nullptr, monitor.get()); });
        }
        if (monitor)
        {
          monitor->RaisePending(); // Ctrl-C, or what a callback raised
        }
        return measured ? sampling : nullptr;
      },
      "points"_a, "threads"_a = 0, "monitor"_a.none() = nb::none(),
      "Measures the nearest-neighbour distances of the points ((n, 3) float64) on `threads` threads (0: all "
      "cores), without the GIL. The monitor (optional) gets the search's progress in its current stage and "
      "may stop it: then None (Ctrl-C raises KeyboardInterrupt).")
    .def("Statistics", &nv::Sampling::Statistics);

  nb::class_<nv::SamplingCache>(m, "SamplingCache",
    "The sampling of a filter's input, measured once per points (nv::SamplingCache).")
    .def(nb::init<>())
    .def(
      "Get",
      [](nv::SamplingCache& cache, const std::tuple<std::string, std::uint64_t, std::int64_t>& key,
        nb::callable points, int threads, std::shared_ptr<PythonMonitor> monitor) {
        nv::Monitor silent;
        nv::Monitor& watch = monitor ? static_cast<nv::Monitor&>(*monitor) : silent;
        // The points are asked for only when measured, on this thread, with the GIL.
        const std::function<std::vector<double>()> xyz = [&points]() {
          nb::gil_scoped_acquire gil;
          const Points array = nb::cast<Points>(points());
          return std::vector<double>(array.data(), array.data() + 3 * array.shape(0));
        };
        std::shared_ptr<const nv::Sampling> sampling;
        bool measured = false;
        {
          nb::gil_scoped_release release;
          sampling = cache.Get({ std::get<0>(key), std::get<1>(key), std::get<2>(key) }, xyz, nullptr, watch,
            threads, &measured);
        }
        if (monitor)
        {
          monitor->RaisePending(); // Ctrl-C, or what a callback raised
        }
        return std::make_pair(std::const_pointer_cast<nv::Sampling>(sampling), measured);
      },
      "key"_a, "points"_a, "threads"_a = 0, "monitor"_a.none() = nb::none(),
      "(sampling, measured): the sampling of the points that points() gives ((n, 3) float64, called only "
      "to measure), measured on `threads` threads without the GIL unless the last measurement had the same "
      "key (the points' object, modification time and count); None if the monitor stopped it.")
    .def("TakeSeconds", &nv::SamplingCache::TakeSeconds,
      "The seconds of the measurements since the last call (the filter's SamplingTime).");

  m.def("InPanelWords", &nv::InPanelWords, "message"_a,
    "The message with the properties' names as the labels of ParaView's panel (nv::InPanelWords).");
  m.def("TableInputError", &nv::TableInputError, "The error for a table given as input (nv::TableInputError).");
  m.def(
    "check_ply_file",
    [](const std::string& path) {
      std::string error;
      return nv::ply::CheckFile(path, error) ? std::string() : error;
    },
    "path"_a,
    "Why the PLY file at `path` cannot be read (nv::ply::CheckFile: its header, counts and data), or an empty "
    "string if vtkPLYReader can read it safely.");
  BindReaders(m);

  m.def(
    "MakePlan",
    [](const nv::Settings& settings, const std::vector<double>& bounds, const nv::SamplingStatistics& sampling) {
      const std::array<double, 6> b = Bounds(bounds);
      return nv::MakePlan(settings, b.data(), sampling);
    },
    "settings"_a, "bounds"_a, "sampling"_a, "The grid for points with these bounds and sampling, or why there is none.");

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

  nb::class_<MeshSink>(m, "MeshSink", "Receives the surface the core makes.")
    .def(nb::init<>())
    .def(
      "Take",
      [](MeshSink& sink) {
        return nb::make_tuple(sink.Points.Release(3), sink.Normals.Release(3), sink.Triangles.Release(3));
      },
      "(points (n, 3) float64, normals (n, 3) float32, triangles (m, 3) int64), without a copy; the sink is "
      "empty afterwards.");

  // Every result of nv::Results (the property table's RESULTS, NV_RESULTS).
  nb::class_<nv::Results> results(m, "Results", "What the run chose (nv::Results): the filter's Get<Name> results.");
  results.def(nb::init<>());
#define NV_BIND_RESULT(Type, Name, Size) results.def_ro(#Name, &nv::Results::Name);
  NV_RESULTS(NV_BIND_RESULT)
#undef NV_BIND_RESULT

  nb::class_<nv::Outcome>(m, "Outcome", "What Reconstruction.Reconstruct made besides its arrays (nv::Outcome).")
    .def_ro("Done", &nv::Outcome::Done)
    .def_ro("Ran", &nv::Outcome::Ran)
    .def_ro("Error", &nv::Outcome::Error)
    .def_ro("Warnings", &nv::Outcome::Warnings)
    .def_ro("VolumeBegin", &nv::Outcome::VolumeBegin)
    .def_ro("VolumeEnd", &nv::Outcome::VolumeEnd)
    .def_ro("DenseArrays", &nv::Outcome::DenseArrays)
    .def_ro("OutputSeconds", &nv::Outcome::OutputSeconds)
    .def_ro("Chosen", &nv::Outcome::Chosen)
    .def_prop_ro(
      "Summary",
      [](const nv::Outcome& outcome) {
        nb::list summary;
        for (const nv::SummaryArray& array : outcome.Summary)
        {
          const char* kind = array.Kind == nv::SummaryArray::Int ? "int"
            : array.Kind == nv::SummaryArray::Id                 ? "id"
                                                                 : "double";
          summary.append(nb::make_tuple(array.Name, kind, array.Components, array.Values, array.ComponentNames));
        }
        return summary;
      },
      "[(name, 'int' | 'id' | 'double', components, values, component names)]: the volume's field data.");

  nb::class_<PythonRun>(m, "Reconstruction", "The whole run of the method (nv::Reconstruction), serial.")
    .def(nb::init<const nv::Settings&, std::shared_ptr<PythonMonitor>, bool>(), "settings"_a,
      "monitor"_a = nb::none(), "host_launcher"_a = false,
      "host_launcher: Device GPU's kernels through the host launcher, on the host's threads (tests and "
      "benchmarks of the device back end without a GPU).")
    .def("Reconstruct", &PythonRun::Reconstruct, "points"_a, "sampling"_a.none(), "sink"_a,
      "The run on the points ((n, 3) float64, C order) and its outputs (nv::Reconstruct), without the GIL: "
      "the surface into the sink, the dense arrays for TakeVolume; returns the Outcome. sampling: the "
      "points' Sampling, if measured already (None: measured here).")
    .def("TakeVolume", &PythonRun::TakeVolume, "{name: numpy array} of the dense arrays the run filled.")
    .def("Aborted", [](const PythonRun& r) { return r.Run.Aborted(); })
    .def("GetSettings", [](const PythonRun& r) { return r.Run.GetSettings(); })
    .def("GetGrid", [](const PythonRun& r) { return r.Run.GetGrid(); })
    .def("GetParameters", [](const PythonRun& r) { return r.Run.GetParameters(); })
    .def("GetPlan", [](const PythonRun& r) { return r.Run.GetPlan(); })
    .def("NumberOfBandNodes", [](const PythonRun& r) { return r.Run.NumberOfBandNodes(); })
    .def("RelativeChanges", [](const PythonRun& r) { return r.Run.RelativeChanges(); })
    .def("SetupSeconds", [](const PythonRun& r) { return r.Run.SetupSeconds(); })
    .def("EvolutionSeconds", [](const PythonRun& r) { return r.Run.EvolutionSeconds(); })
    .def("DeviceUsed", [](const PythonRun& r) { return r.Run.DeviceName(); },
      "\"CPU\", \"GPU\", or \"GPU on the host\" (host_launcher): where the run computed.")
    .def("DeviceBytes", [](const PythonRun& r) { return r.Run.DeviceBytes(); },
      "The most bytes the GPU held at once (0 on the CPU).")
    .def(
      "DeviceCopies",
      [](const PythonRun& r) {
        const nv::CopyCounts c = r.Run.DeviceCopies();
        return nb::make_tuple(c.ToHostBytes, c.ToHostSeconds, c.ToDeviceBytes, c.ToDeviceSeconds);
      },
      "The run's copies between the host and the GPU: (bytes to the host, their seconds, bytes to the GPU, "
      "their seconds); zeros on the CPU and through the host launcher.");

  m.attr("SamplingStage") = nv::SamplingStage;
}
