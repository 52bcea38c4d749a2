// Philox streams: the same address gives the same bits; draws do not depend on
// the order streams are used in; different purposes, trials and decisions are
// uncorrelated; uniform and normal draws have the right first two moments.
//
// Statistical checks use N = 200000 draws and bounds of 5 standard errors:
// a correct generator fails one with probability below 1e-6.
#include "vahf/rng/stream.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace vahf::rng {
namespace {

constexpr int kN = 200000;

std::vector<double> Uniforms(StreamKey key, std::uint64_t decision, Purpose p, int n) {
  Stream s(key, decision, p);
  std::vector<double> out(n);
  for (double& x : out) x = s.Uniform();
  return out;
}

double Correlation(const std::vector<double>& a, const std::vector<double>& b) {
  const double n = static_cast<double>(a.size());
  double ma = 0, mb = 0;
  for (std::size_t i = 0; i < a.size(); ++i) ma += a[i], mb += b[i];
  ma /= n, mb /= n;
  double sab = 0, saa = 0, sbb = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    sab += (a[i] - ma) * (b[i] - mb);
    saa += (a[i] - ma) * (a[i] - ma);
    sbb += (b[i] - mb) * (b[i] - mb);
  }
  return sab / std::sqrt(saa * sbb);
}

TEST(Stream, SameAddressSameBits) {
  Stream a({42, 7}, 3, Purpose::kTargetEstimate);
  Stream b({42, 7}, 3, Purpose::kTargetEstimate);
  for (int i = 0; i < 1000; ++i) ASSERT_EQ(a.Bits(), b.Bits()) << "draw " << i;
}

TEST(Stream, KnownAnswer) {
  // Random123's published known-answer vector for Philox4x64-10 (kat_vectors,
  // line "philox4x64 10", counter and key all zero). Lane 0 is not a Purpose a
  // trial uses; it addresses the all-zero counter. A change of generator,
  // rounds or word order, which would silently change every seeded result,
  // fails here.
  Stream s({0, 0}, 0, static_cast<Purpose>(0));
  EXPECT_EQ(s.Bits(), UINT64_C(0x16554d9eca36314c));
  EXPECT_EQ(s.Bits(), UINT64_C(0xdb20fe9d672d0fdc));
  EXPECT_EQ(s.Bits(), UINT64_C(0xd7e772cee186176b));
  EXPECT_EQ(s.Bits(), UINT64_C(0x7e68b68aec7ba23b));
}

TEST(Stream, EveryAddressFieldChangesTheBits) {
  const std::uint64_t base = Stream({1, 2}, 3, Purpose::kVisionError).Bits();
  EXPECT_NE(base, Stream({9, 2}, 3, Purpose::kVisionError).Bits());
  EXPECT_NE(base, Stream({1, 9}, 3, Purpose::kVisionError).Bits());
  EXPECT_NE(base, Stream({1, 2}, 9, Purpose::kVisionError).Bits());
  EXPECT_NE(base, Stream({1, 2}, 3, Purpose::kTargetEstimate).Bits());
}

TEST(Stream, OrderOfUseDoesNotMatter) {
  // Interleave two streams one way, then the other way; each sees the same values.
  Stream a1({5, 1}, 10, Purpose::kTargetEstimate), b1({5, 1}, 10, Purpose::kVisionError);
  std::vector<double> a_first, b_first;
  for (int i = 0; i < 50; ++i) a_first.push_back(a1.Uniform());
  for (int i = 0; i < 50; ++i) b_first.push_back(b1.Normal());
  Stream a2({5, 1}, 10, Purpose::kTargetEstimate), b2({5, 1}, 10, Purpose::kVisionError);
  std::vector<double> a_second, b_second;
  for (int i = 0; i < 50; ++i) {
    b_second.push_back(b2.Normal());
    a_second.push_back(a2.Uniform());
  }
  EXPECT_EQ(a_first, a_second);
  EXPECT_EQ(b_first, b_second);
}

TEST(Stream, UniformMoments) {
  const auto u = Uniforms({3, 0}, 0, Purpose::kTest, kN);
  double mean = 0, var = 0;
  for (double x : u) {
    ASSERT_GT(x, 0.0);
    ASSERT_LE(x, 1.0);
    mean += x;
  }
  mean /= kN;
  for (double x : u) var += (x - mean) * (x - mean);
  var /= kN - 1;
  EXPECT_NEAR(mean, 0.5, 5 * std::sqrt(1.0 / 12 / kN));
  EXPECT_NEAR(var, 1.0 / 12, 5 * std::sqrt(1.0 / 180 / kN));  // Var of s^2 for U(0,1)
}

TEST(Stream, NormalMoments) {
  Stream s({4, 0}, 0, Purpose::kTest);
  double mean = 0, m2 = 0, m4 = 0;
  for (int i = 0; i < kN; ++i) {
    const double x = s.Normal();
    mean += x, m2 += x * x, m4 += x * x * x * x;
  }
  mean /= kN, m2 /= kN, m4 /= kN;
  EXPECT_NEAR(mean, 0.0, 5 / std::sqrt(kN));
  EXPECT_NEAR(m2, 1.0, 5 * std::sqrt(2.0 / kN));
  EXPECT_NEAR(m4, 3.0, 5 * std::sqrt(96.0 / kN));  // Var(x^4) = 105 - 9
}

TEST(Stream, PurposesTrialsAndDecisionsAreUncorrelated) {
  const double bound = 5 / std::sqrt(kN);
  const auto base = Uniforms({7, 0}, 0, Purpose::kTargetEstimate, kN);
  EXPECT_LT(std::abs(Correlation(base, Uniforms({7, 0}, 0, Purpose::kVisionError, kN))),
            bound);
  EXPECT_LT(
      std::abs(Correlation(base, Uniforms({7, 1}, 0, Purpose::kTargetEstimate, kN))),
      bound);
  EXPECT_LT(
      std::abs(Correlation(base, Uniforms({7, 0}, 1, Purpose::kTargetEstimate, kN))),
      bound);
  EXPECT_LT(
      std::abs(Correlation(base, Uniforms({8, 0}, 0, Purpose::kTargetEstimate, kN))),
      bound);
  // Serial correlation within one stream.
  std::vector<double> lag0(base.begin(), base.end() - 1),
      lag1(base.begin() + 1, base.end());
  EXPECT_LT(std::abs(Correlation(lag0, lag1)), bound);
}

TEST(Stream, FirstDrawsAcrossTrialsAreUniform) {
  // The first draw of each of many trials (the Monte Carlo case): a chi-square
  // test on 20 bins; the 1e-6 quantile of chi-square with 19 dof is 62.6.
  constexpr int kBins = 20;
  std::vector<int> count(kBins, 0);
  for (int t = 0; t < kN; ++t) {
    const double u =
        Stream({11, static_cast<std::uint64_t>(t)}, 0, Purpose::kTest).Uniform();
    ++count[std::min(kBins - 1, static_cast<int>(u * kBins))];
  }
  double chi2 = 0;
  const double expected = static_cast<double>(kN) / kBins;
  for (int c : count) chi2 += (c - expected) * (c - expected) / expected;
  EXPECT_LT(chi2, 62.6);
}

}  // namespace
}  // namespace vahf::rng
