// Private to CVT::Core: what the L-BFGS drivers share. LBFGS++'s More-Thuente line search,
// reporting every accepted iterate to the objective (f.AcceptIterate), so that the optimisers
// keep a history per iteration and can stop the solver from there by throwing StopOptimizer.
#ifndef cvtReportingLineSearch_h
#define cvtReportingLineSearch_h

#include <Eigen/Core>
#include <LBFGSB.h>

#include <string>

namespace cvt
{

/// Thrown from inside the solver to end it: a stop condition, or an engine failure.
struct StopOptimizer
{
  std::string Reason;
  bool EngineFailed;
};

/// LBFGS++'s More-Thuente line search, reporting every accepted iterate to the objective.
template<typename Scalar>
class ReportingLineSearch
{
public:
  using Vector = Eigen::Matrix<Scalar, Eigen::Dynamic, 1>;
  template<typename Function>
  static void LineSearch(Function& f, Scalar& fx, Vector& x, Vector& grad, Scalar& step,
    const Scalar& stepMax, const Vector& direction, const Vector& previous,
    const LBFGSpp::LBFGSBParam<Scalar>& param)
  {
    LBFGSpp::LineSearchMoreThuente<Scalar>::LineSearch(
      f, fx, x, grad, step, stepMax, direction, previous, param);
    f.AcceptIterate(fx, grad);
  }
};

} // namespace cvt

#endif
