#include "nvParallel.h"

#include <vtkSMPTools.h>

#include <algorithm>
#include <vector>

namespace nv
{
namespace
{
// Chunk size of the deterministic reductions: fixed, never derived from the thread count.
constexpr std::int64_t ReductionChunk = 8192;

std::vector<double> ChunkValues(std::int64_t n, const RangeReduction& fn)
{
  const std::int64_t chunks = (n + ReductionChunk - 1) / ReductionChunk;
  std::vector<double> values(static_cast<std::size_t>(chunks), 0.0);
  ParallelFor(0, chunks, 1, [&](std::int64_t first, std::int64_t last) {
    for (std::int64_t c = first; c < last; ++c)
    {
      const std::int64_t begin = c * ReductionChunk;
      values[static_cast<std::size_t>(c)] = fn(begin, std::min(n, begin + ReductionChunk));
    }
  });
  return values;
}
} // namespace

void ParallelFor(std::int64_t begin, std::int64_t end, std::int64_t grain, const RangeFunction& fn)
{
  if (end <= begin)
  {
    return;
  }
  vtkSMPTools::For(begin, end, std::max<std::int64_t>(grain, 1),
    [&fn](std::int64_t first, std::int64_t last) { fn(first, last); });
}

double ParallelSum(std::int64_t n, const RangeReduction& fn)
{
  double sum = 0.0;
  for (double v : ChunkValues(n, fn))
  {
    sum += v;
  }
  return sum;
}

double ParallelMax(std::int64_t n, const RangeReduction& fn)
{
  double result = 0.0;
  for (double v : ChunkValues(n, fn))
  {
    result = std::max(result, v);
  }
  return result;
}

Monitor::~Monitor() = default;
void Monitor::Progress(double) {}
bool Monitor::Aborted()
{
  return false;
}

} // namespace nv
