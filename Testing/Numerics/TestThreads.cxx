#include "cvtThreads.h"

#include "vtkSMPTools.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <mutex>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace
{
using Chunks = std::vector<std::pair<vtkIdType, vtkIdType>>;

/// The chunks one cvt::For hands out, sorted.
Chunks ChunksOf(vtkIdType first, vtkIdType last, vtkIdType grain)
{
  Chunks chunks;
  std::mutex mutex;
  cvt::For(first, last, grain,
    [&](vtkIdType begin, vtkIdType end)
    {
      const std::lock_guard<std::mutex> lock(mutex);
      chunks.emplace_back(begin, end);
    });
  std::sort(chunks.begin(), chunks.end());
  return chunks;
}

/// The chunks vtkSMPTools::For's STDThread backend cuts [first, last) into.
Chunks Expected(vtkIdType first, vtkIdType last, vtkIdType grain, int threads)
{
  if (grain <= 0)
  {
    grain = std::max<vtkIdType>(1, (last - first) / (threads * 4));
  }
  Chunks chunks;
  for (vtkIdType begin = first; begin < last; begin += grain)
  {
    chunks.emplace_back(begin, std::min(last, begin + grain));
  }
  return chunks;
}

/// Called by each of two chunks of a loop: waits until the other has started too, which it
/// does only when two threads run them at once (else it gives up after five seconds). True
/// when they met.
bool MeetTheOtherChunk(std::atomic<int>& started)
{
  ++started;
  const auto giveUp = std::chrono::steady_clock::now() + std::chrono::seconds(5);
  while (started.load() < 2 && std::chrono::steady_clock::now() < giveUp)
  {
    std::this_thread::yield();
  }
  return started.load() == 2;
}

/// Threads for the test's run: the STDThread backend with two threads, restored after.
class Threads : public ::testing::Test
{
protected:
  void SetUp() override
  {
    this->Backend = vtkSMPTools::GetBackend();
    vtkSMPTools::SetBackend("STDThread");
    vtkSMPTools::Initialize(2);
  }
  void TearDown() override { vtkSMPTools::SetBackend(this->Backend.c_str()); }
  std::string Backend;
};
}

TEST_F(Threads, ChunksAreVtkSMPToolsChunks)
{
  // Results that depend on where a chunk starts (a search hint carried along a chunk) stay
  // those of vtkSMPTools::For and do not depend on the threads' timing.
  const int threads = vtkSMPTools::GetEstimatedNumberOfThreads();
  EXPECT_EQ(ChunksOf(0, 1000, 256), Expected(0, 1000, 256, threads));
  EXPECT_EQ(ChunksOf(7, 10007, 1), Expected(7, 10007, 1, threads));
  EXPECT_EQ(ChunksOf(0, 1001, 0), Expected(0, 1001, 0, threads));
  EXPECT_EQ(ChunksOf(3, 50, 100), Chunks({ { 3, 50 } })); // one chunk: run as it is
  EXPECT_TRUE(ChunksOf(5, 5, 1).empty());
  EXPECT_TRUE(ChunksOf(5, 4, 1).empty());
}

TEST_F(Threads, ChunksRunAtOnce)
{
  if (vtkSMPTools::GetEstimatedNumberOfThreads() < 2)
  {
    GTEST_SKIP() << "one thread only";
  }
  std::atomic<int> started{ 0 };
  std::atomic<int> metTheOther{ 0 };
  cvt::For(0, 2, 1,
    [&](vtkIdType, vtkIdType)
    {
      if (MeetTheOtherChunk(started))
      {
        ++metTheOther;
      }
    });
  EXPECT_EQ(metTheOther.load(), 2);
}

TEST_F(Threads, WorkerThreadsStayBetweenLoops)
{
  if (vtkSMPTools::GetEstimatedNumberOfThreads() < 2)
  {
    GTEST_SKIP() << "one thread only";
  }
  // Loops of two chunks that run at once (as above), one of them on a worker thread. A worker
  // that ran a chunk of an earlier loop still has its thread-local count; threads started for
  // each loop (vtkSMPTools' STDThread backend in VTK 9.2) never have. With more loops than the
  // machine has threads, some worker must have run two of them.
  static thread_local int chunksRun = 0;
  const std::thread::id caller = std::this_thread::get_id();
  const int loops = 2 * static_cast<int>(std::thread::hardware_concurrency()) + 2;
  std::atomic<int> workerChunks{ 0 }, workerReturns{ 0 };
  for (int loop = 0; loop < loops; ++loop)
  {
    std::atomic<int> started{ 0 };
    cvt::For(0, 2, 1,
      [&](vtkIdType, vtkIdType)
      {
        MeetTheOtherChunk(started);
        if (std::this_thread::get_id() != caller)
        {
          ++workerChunks;
          workerReturns += chunksRun > 0 ? 1 : 0;
        }
        ++chunksRun;
      });
  }
  EXPECT_EQ(workerChunks.load(), loops);
  EXPECT_GT(workerReturns.load(), 0);
}

TEST_F(Threads, LoopsInALoopRunSerially)
{
  // As vtkSMPTools has them (nesting off): a loop in a loop's body is one chunk, on the
  // thread of the outer chunk.
  std::mutex mutex;
  std::vector<Chunks> inner;
  cvt::For(0, 4, 1,
    [&](vtkIdType, vtkIdType)
    {
      const std::thread::id outer = std::this_thread::get_id();
      Chunks seen;
      bool sameThread = true;
      cvt::For(0, 1000, 10,
        [&](vtkIdType begin, vtkIdType end)
        {
          seen.emplace_back(begin, end);
          sameThread = sameThread && std::this_thread::get_id() == outer;
        });
      EXPECT_TRUE(sameThread);
      const std::lock_guard<std::mutex> lock(mutex);
      inner.push_back(seen);
    });
  ASSERT_EQ(inner.size(), 4u);
  for (const Chunks& seen : inner)
  {
    EXPECT_EQ(seen, Chunks({ { 0, 1000 } }));
  }
  // After the loop, loops are parallel again.
  EXPECT_EQ(ChunksOf(0, 100, 10).size(), 10u);
}

TEST_F(Threads, SequentialBackendRunsTheChunksInOrder)
{
  vtkSMPTools::SetBackend("Sequential");
  Chunks order;
  const std::thread::id caller = std::this_thread::get_id();
  bool sameThread = true;
  cvt::For(0, 10, 3,
    [&](vtkIdType begin, vtkIdType end)
    {
      order.emplace_back(begin, end);
      sameThread = sameThread && std::this_thread::get_id() == caller;
    });
  EXPECT_EQ(order, Chunks({ { 0, 3 }, { 3, 6 }, { 6, 9 }, { 9, 10 } }));
  EXPECT_TRUE(sameThread);
  order.clear();
  cvt::For(0, 10, [&](vtkIdType begin, vtkIdType end) { order.emplace_back(begin, end); });
  EXPECT_EQ(order, Chunks({ { 0, 10 } }));
}
