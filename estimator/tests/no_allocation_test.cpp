// The solve allocates nothing: it reads the samples in place (no arrays of its own), so no
// allocation depends on the number of iterations or of samples, and there is none at all. Counted by wrapping glibc's malloc and realloc in this test program alone (operator
// new and Eigen both allocate through them); not under AddressSanitizer, which owns malloc.
#include <atomic>
#include <cstddef>
#include <vector>

#include <gtest/gtest.h>

#include "anchorbench/estimator/anchor_solver.hpp"
#include "anchorbench/estimator/nls_solver.hpp"
#include "anchorbench/testing/test_data.hpp"

namespace {
std::atomic<long> g_allocations{0};
}  // namespace

#if defined(__SANITIZE_ADDRESS__)  // GCC
#define ANCHORBENCH_UNDER_ASAN 1
#elif defined(__has_feature)  // clang
#if __has_feature(address_sanitizer)
#define ANCHORBENCH_UNDER_ASAN 1
#endif
#endif

#if defined(ANCHORBENCH_UNDER_ASAN)
#define ANCHORBENCH_COUNTS_ALLOCATIONS 0
#else
#define ANCHORBENCH_COUNTS_ALLOCATIONS 1
extern "C" {
void* __libc_malloc(std::size_t size);
void* __libc_realloc(void* p, std::size_t size);
void* malloc(std::size_t size) {
  ++g_allocations;
  return __libc_malloc(size);
}
void* realloc(void* p, std::size_t size) {
  ++g_allocations;
  return __libc_realloc(p, size);
}
}
#endif

namespace anchorbench::estimator {
namespace {

struct Counted {
  long allocations;
  int iterations;
};

Counted Solve(const NlsOptions& options, int n) {
  auto rng = testing::TestStream(500);
  const Eigen::Vector3d p_anchor(1, 2, 3);
  const auto data = testing::BoxData(rng, n, p_anchor, Eigen::Vector3d(4, 0, 1), 5.0, 0.1, 0.05);
  const NlsSolver solver(options);
  const long before = g_allocations;
  const SolveResult result = solver.Solve(data.p_world_tag, data.range_m, Eigen::Vector3d(7, -2, 0), 0.0);
  return {g_allocations - before, result.iterations};
}

TEST(NoAllocation, TheNlsLoopAllocatesNothingWhateverItsIterationsOrSamples) {
  if (!ANCHORBENCH_COUNTS_ALLOCATIONS) GTEST_SKIP() << "AddressSanitizer owns malloc";
  for (KernelMode kernel : {KernelMode::kL2, KernelMode::kAdaptive, KernelMode::kFixed}) {
    NlsOptions options;
    options.kernel = kernel;
    options.max_iterations = 1;
    const Counted one = Solve(options, 300);
    options.max_iterations = 50;
    const Counted many = Solve(options, 300);
    const Counted large = Solve(options, 30000);
    ASSERT_GT(many.iterations, one.iterations + 3) << ToString(kernel);
    EXPECT_EQ(one.allocations, 0) << ToString(kernel);
    EXPECT_EQ(many.allocations, 0) << ToString(kernel);
    EXPECT_EQ(large.allocations, 0) << ToString(kernel);
  }
}

// The counting works: an allocation the test makes itself is counted.
TEST(NoAllocation, TheCountSeesAnAllocation) {
  if (!ANCHORBENCH_COUNTS_ALLOCATIONS) GTEST_SKIP() << "AddressSanitizer owns malloc";
  const long before = g_allocations;
  const std::vector<double> buffer(1000, 1.0);
  EXPECT_GT(g_allocations - before, 0);
  EXPECT_EQ(buffer.size(), 1000u);
}

}  // namespace
}  // namespace anchorbench::estimator
