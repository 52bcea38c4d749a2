#include "vahf/human/learning.h"

#include <cmath>

#include "vahf/core/error.h"

namespace vahf::human {

double PracticeTimeFactor(const LearningParams& params, int repetition) {
  VAHF_CHECK(repetition >= 1, "repetitions count from 1");
  if (params.model == "none" || repetition == 1) return 1.0;
  const double floor = params.model == "de_jong" ? params.floor : 0.0;
  return floor +
         (1.0 - floor) * std::pow(static_cast<double>(repetition), -params.exponent);
}

double PracticeGain(const LearningParams& params, int repetition) {
  const double l = PracticeTimeFactor(params, repetition);
  return 1.0 / (l * l);
}

}  // namespace vahf::human
