#include "cvtThreads.h"

#include "vtkSMPTools.h"

#include <tbb/info.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <memory>
#include <mutex>
#include <string>

namespace cvt
{
namespace
{
/// Set while a loop runs: a loop started meanwhile (in its body, or by another thread) runs
/// serially, as vtkSMPTools' IsParallel makes it.
std::atomic<bool> InParallel{ false };

/// Whether vtkSMPTools runs its loops on the calling thread alone.
bool SequentialBackend()
{
  const char* backend = vtkSMPTools::GetBackend();
  return backend && std::string(backend) == "Sequential";
}

/// The worker threads, kept between loops; made again when vtkSMPTools' count changes (a loop
/// still running on the former ones holds them until it ends).
std::shared_ptr<tbb::task_arena> Arena(int threads)
{
  static std::mutex mutex;
  static std::shared_ptr<tbb::task_arena> arena;
  const std::lock_guard<std::mutex> lock(mutex);
  if (!arena || arena->max_concurrency() != threads)
  {
    arena = std::make_shared<tbb::task_arena>(threads);
  }
  return arena;
}
}

//------------------------------------------------------------------------------
void UseThreads()
{
  if (SequentialBackend() && !std::getenv("VTK_SMP_BACKEND_IN_USE"))
  {
    vtkSMPTools::SetBackend("STDThread");
  }
}

//------------------------------------------------------------------------------
void ForChunks(vtkIdType first, vtkIdType last, vtkIdType grain,
  const std::function<void(vtkIdType, vtkIdType)>& chunk)
{
  const vtkIdType n = last - first;
  if (n <= 0)
  {
    return;
  }
  // No more than oneTBB may start (the processor affinity mask can allow fewer than VTK counts).
  const int threads = SequentialBackend()
    ? 1
    : std::max(
        1, std::min(vtkSMPTools::GetEstimatedNumberOfThreads(), tbb::info::default_concurrency()));
  if (threads == 1)
  {
    // vtkSMPTools' Sequential backend: the chunks in order.
    const vtkIdType step = grain > 0 ? grain : n;
    for (vtkIdType begin = first; begin < last; begin += step)
    {
      chunk(begin, std::min(last, begin + step));
    }
    return;
  }
  if (grain <= 0)
  {
    grain = std::max<vtkIdType>(1, n / (threads * 4));
  }
  if (grain >= n || InParallel.load())
  {
    chunk(first, last);
    return;
  }
  struct Running // until the loop ends, by return or exception
  {
    const bool FromParallel = InParallel.exchange(true);
    ~Running()
    {
      if (!this->FromParallel)
      {
        InParallel.store(false);
      }
    }
  } running;
  const vtkIdType chunks = (n + grain - 1) / grain;
  Arena(threads)->execute(
    [&]()
    {
      tbb::parallel_for(
        vtkIdType(0), chunks,
        [&](vtkIdType k)
        {
          const vtkIdType begin = first + k * grain;
          chunk(begin, std::min(last, begin + grain));
        },
        tbb::simple_partitioner());
    });
}
}
