// Two engines that play two MPI ranks sharing their cell sums (SharedCellSums::ShareWork), for
// the core's tests: part 1 hands its packed sums over (and keeps its own), part 0 adds them to
// its own. Compute part 1's sums first.
#ifndef cvtTwoRanks_h
#define cvtTwoRanks_h

#include "cvtEngine.h"

#include <vector>

namespace cvttest
{

/// Makes `partZero` and `partOne` the two parts; `fromPartOne` receives what part 1 sends.
inline void PlayTwoRanks(
  cvt::SharedCellSums& partZero, cvt::SharedCellSums& partOne, std::vector<double>& fromPartOne)
{
  partOne.ShareWork(1, 2,
    [&fromPartOne](std::vector<double>& sums)
    {
      fromPartOne = sums;
      return true;
    });
  partZero.ShareWork(0, 2,
    [&fromPartOne](std::vector<double>& sums)
    {
      for (size_t k = 0; k < sums.size() && k < fromPartOne.size(); ++k)
      {
        sums[k] += fromPartOne[k];
      }
      return true;
    });
}

} // namespace cvttest

#endif
