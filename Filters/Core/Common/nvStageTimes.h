// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// Where a run's time goes: the wall-clock seconds of its stages, in the
// order they ran, for the field data "StageSeconds" (nvReconstruct.h), the
// command line's --timings and the stage benchmark (benchmarks/stages.py).
#ifndef nvStageTimes_h
#define nvStageTimes_h

#include <chrono>
#include <string>
#include <utility>
#include <vector>

namespace nv
{

class StageTimes
{
public:
  using Clock = std::chrono::steady_clock;

  /// Adds the seconds from `start` to now to the stage `name` (a stage run
  /// twice adds up).
  void Add(const std::string& name, Clock::time_point start)
  {
    this->Add(name, std::chrono::duration<double>(Clock::now() - start).count());
  }
  void Add(const std::string& name, double seconds)
  {
    for (auto& stage : this->Stages)
    {
      if (stage.first == name)
      {
        stage.second += seconds;
        return;
      }
    }
    this->Stages.emplace_back(name, seconds);
  }

  /// Runs fn() as the stage `name` and returns what it returns.
  template <typename Fn>
  auto Time(const std::string& name, Fn&& fn) -> decltype(fn())
  {
    struct Stop
    {
      StageTimes* Times;
      const std::string& Name;
      Clock::time_point Start;
      ~Stop() { this->Times->Add(this->Name, this->Start); }
    } stop{ this, name, Clock::now() };
    return fn();
  }

  const std::vector<std::pair<std::string, double>>& Get() const { return this->Stages; }

private:
  std::vector<std::pair<std::string, double>> Stages;
};

} // namespace nv

#endif
