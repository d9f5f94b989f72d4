// SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
// SPDX-License-Identifier: BSD-3-Clause
// The pool of nvThreadPool.h.
//
// Results do not depend on it: nvParallel.cxx reduces over fixed chunks, and
// every other loop of the core writes each index independently. What the
// pool decides is only which thread computes which chunk.
//
// - The workers start when a loop first needs them and live as long as the
//   process (the pool is never destroyed, so no thread outlives its mutex).
// - One loop at a time: a loop started while another thread's loop holds the
//   pool (two reconstructions in two Python threads), or from inside a loop,
//   runs on its own thread.
// - A child process made by fork() has none of its parent's threads: it gets
//   a fresh pool.
#include "nvThreadPool.h"

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <thread>

#ifdef _WIN32
#include <process.h>
#define nv_getpid _getpid
#else
#include <unistd.h>
#define nv_getpid getpid
#endif

namespace nv
{
namespace
{
thread_local bool InLoop = false; // this thread is running a chunk of a pool loop

class Pool
{
public:
  static Pool& Instance();

  /// Runs fn over [begin, end) in chunks of `grain` on `threads` threads: the caller and threads - 1 workers.
  void Run(std::int64_t begin, std::int64_t end, std::int64_t grain, int threads, const RangeFunction& fn)
  {
    std::unique_lock<std::mutex> mine(this->OneLoop, std::try_to_lock);
    if (!mine.owns_lock())
    {
      for (std::int64_t first = begin; first < end; first += grain)
      {
        fn(first, std::min(end, first + grain));
      }
      return;
    }
    {
      std::lock_guard<std::mutex> guard(this->Lock);
      for (; this->Workers < threads - 1; ++this->Workers)
      {
        std::thread(&Pool::Work, this, this->Workers).detach();
      }
      this->Job = &fn;
      this->Next = begin;
      this->End = end;
      this->Grain = grain;
      this->Helpers = threads - 1;
      this->Open = true;
      this->Busy = 0;
      this->Failure = nullptr;
      ++this->Generation;
    }
    this->Started.notify_all();
    this->TakeChunks();
    // Every chunk is taken: wait for the workers still computing one, not
    // for those that have not woken up yet (on a loaded machine that can
    // take longer than the loop), which will find the loop closed.
    std::unique_lock<std::mutex> wait(this->Lock);
    this->Open = false;
    this->Finished.wait(wait, [this] { return this->Busy == 0; });
    this->Job = nullptr;
    if (this->Failure)
    {
      std::rethrow_exception(this->Failure);
    }
  }

private:
  Pool() = default;

  /// A worker: joins each loop that wants it, until the process ends.
  void Work(int index)
  {
    std::uint64_t seen = 0;
    for (;;)
    {
      {
        std::unique_lock<std::mutex> wait(this->Lock);
        this->Started.wait(wait, [&] { return this->Generation != seen; });
        seen = this->Generation;
        if (index >= this->Helpers || !this->Open)
        {
          continue; // a loop with fewer threads, or one already done
        }
        ++this->Busy;
      }
      this->TakeChunks();
      std::lock_guard<std::mutex> guard(this->Lock);
      if (--this->Busy == 0)
      {
        this->Finished.notify_one();
      }
    }
  }

  /// Chunks of the current loop, until none is left.
  void TakeChunks()
  {
    InLoop = true;
    for (;;)
    {
      const std::int64_t first = this->Next.fetch_add(this->Grain);
      if (first >= this->End)
      {
        break;
      }
      try
      {
        (*this->Job)(first, std::min(this->End, first + this->Grain));
      }
      catch (...)
      {
        std::lock_guard<std::mutex> guard(this->Lock);
        if (!this->Failure)
        {
          this->Failure = std::current_exception();
        }
      }
    }
    InLoop = false;
  }

  std::mutex OneLoop; // held by the thread whose loop uses the pool
  std::mutex Lock;    // guards what follows, but Next
  std::condition_variable Started;
  std::condition_variable Finished;
  int Workers = 0;
  std::uint64_t Generation = 0;
  int Helpers = 0;    // workers that may take part in the current loop
  bool Open = false;  // whether workers may still join it
  int Busy = 0;       // workers computing its chunks
  const RangeFunction* Job = nullptr;
  std::atomic<std::int64_t> Next{ 0 };
  std::int64_t End = 0;
  std::int64_t Grain = 1;
  std::exception_ptr Failure;

public:
  const decltype(nv_getpid()) Owner = nv_getpid();
};

Pool& Pool::Instance()
{
  static std::atomic<Pool*> current{ new Pool };
  Pool* pool = current.load();
  if (pool->Owner != nv_getpid())
  {
    // A forked child: the parent's pool (and its threads) stays behind.
    Pool* fresh = new Pool;
    if (current.compare_exchange_strong(pool, fresh))
    {
      pool = fresh;
    }
    else
    {
      delete fresh;
    }
  }
  return *pool;
}
} // namespace

void PoolFor(std::int64_t begin, std::int64_t end, std::int64_t grain, int threads, const RangeFunction& fn)
{
  Pool::Instance().Run(begin, end, grain, std::max(1, threads), fn);
}

bool InPoolLoop()
{
  return InLoop;
}

} // namespace nv
