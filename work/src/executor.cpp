#include "anchorbench/work/executor.hpp"

#include <exception>

namespace anchorbench::work {

void LocalExecutor::Compute(const Plan& plan, const std::vector<int>& chunks, int threads, const ChunkDone& done) {
  const int count = static_cast<int>(chunks.size());
  std::exception_ptr first_error;
  int first_error_at = count;
#pragma omp parallel num_threads(threads)
  {
    // One sample buffer per thread, reused from unit to unit (megabytes per realization).
    std::vector<estimator::RangeSample> samples;
#pragma omp for schedule(dynamic, 1)
    for (int i = 0; i < count; ++i) {
      const int chunk = chunks[static_cast<std::size_t>(i)];
      try {  // an exception must not leave the parallel region (std::terminate)
        ChunkResult result = ComputeChunk(plan, chunk, components_, samples);
        const std::string text = ChunkText(result);
#pragma omp critical(anchorbench_chunk_done)
        done(chunk, std::move(result), text);
      } catch (...) {
#pragma omp critical(anchorbench_chunk_error)
        if (i < first_error_at) {  // the first in list order, whatever the timing
          first_error_at = i;
          first_error = std::current_exception();
        }
      }
    }
  }
  if (first_error) std::rethrow_exception(first_error);
}

}  // namespace anchorbench::work
