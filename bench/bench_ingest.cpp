// What one process does for every chunk it receives: rank 0 of an MPI job, or a run keeping its
// chunk store. Rank 0 takes a chunk from its records and text (engine::FromRecords: the text split
// into lines, not parsed) and saves the text to the store (one file). Rank 0 does this one chunk
// at a time, so it bounds how fast a job can go however many ranks compute (docs/cluster.md's cost
// model). Beside it, what reading a chunk's text back costs (engine::ParseChunk: a resumed run's,
// a shard folder's, and rank 0's before records). The chunks are Table I's at its 100
// realizations (two units a chunk), a 1-in-8 share of them.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <map>
#include <optional>
#include <string>

#include "anchorbench/config/load_config.hpp"
#include "anchorbench/eval/oracles.hpp"
#include "anchorbench/engine/run_plan.hpp"

namespace ab = anchorbench;

namespace {

struct Chunks {
  ab::registry::Components components = ab::eval::MakeComponentsWithOracles();
  ab::engine::Plan plan{{ab::config::LoadConfig(ANCHORBENCH_SOURCE_DIR "/configs/table1.yaml", {}, components)}};
  std::map<int, std::string> texts, records;
  long long units = 0;

  Chunks() {
    ab::engine::LocalExecutor executor(components);
    class Texts final : public ab::engine::Executor {  // keeps each chunk's text as it is computed
     public:
      Texts(ab::engine::Executor& inner, Chunks& into) : inner_(inner), into_(into) {}
      void Compute(const ab::engine::Plan& p, const std::vector<int>& chunks, int threads,
                   const ab::engine::ChunkDone& done) override {
        inner_.Compute(p, chunks, threads, [&](int chunk, ab::engine::ChunkResult&& result, const std::string& text) {
          into_.texts[chunk] = text;
          into_.records[chunk] = ab::engine::ChunkRecords(p, chunk, result);
          done(chunk, std::move(result), text);
        });
      }

     private:
      ab::engine::Executor& inner_;
      Chunks& into_;
    } keeping(executor, *this);
    ab::engine::RunPlan(plan, keeping, {2, nullptr, nullptr, ab::engine::Shard{0, 8}});
    for (const auto& [chunk, text] : texts) {
      const ab::engine::ChunkSpan& span = plan.chunks()[static_cast<std::size_t>(chunk)];
      units += span.end_unit - span.first_unit;
    }
  }
};

const Chunks& TableOneChunks() {
  static const Chunks chunks;
  return chunks;
}

// items_per_second: units a second.
void Report(benchmark::State& state, long long units) {
  state.SetItemsProcessed(state.iterations() * units);
  state.counters["units"] = static_cast<double>(units);
}

void BM_ParseChunkPerUnit(benchmark::State& state) {
  const Chunks& chunks = TableOneChunks();
  for (auto _ : state) {
    for (const auto& [chunk, text] : chunks.texts) {
      benchmark::DoNotOptimize(ab::engine::ParseChunk(chunks.plan, chunk, text, "bench"));
    }
  }
  Report(state, chunks.units);
}
BENCHMARK(BM_ParseChunkPerUnit)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_RecordsChunkPerUnit(benchmark::State& state) {
  const Chunks& chunks = TableOneChunks();
  for (auto _ : state) {
    for (const auto& [chunk, text] : chunks.texts) {
      benchmark::DoNotOptimize(ab::engine::FromRecords(chunks.plan, chunk, text, chunks.records.at(chunk), "bench"));
    }
  }
  Report(state, chunks.units);
}
BENCHMARK(BM_RecordsChunkPerUnit)->Unit(benchmark::kMillisecond)->UseRealTime();

// Rank 0's work a chunk: its records taken, its text saved (`records`), or its text parsed and
// saved (`!records`: rank 0 before records).
void IngestAndStore(benchmark::State& state, bool records) {
  const Chunks& chunks = TableOneChunks();
  const std::filesystem::path out = std::filesystem::temp_directory_path() / "anchorbench_bench_ingest";
  for (auto _ : state) {
    state.PauseTiming();  // the store's own start and end are once a run, not once a chunk
    std::optional<ab::engine::ChunkStore> store;
    store.emplace(out, chunks.plan, ab::engine::ChunkStore::Mode::kOverwrite);
    state.ResumeTiming();
    for (const auto& [chunk, text] : chunks.texts) {
      if (records) {
        benchmark::DoNotOptimize(ab::engine::FromRecords(chunks.plan, chunk, text, chunks.records.at(chunk), "bench"));
      } else {
        benchmark::DoNotOptimize(ab::engine::ParseChunk(chunks.plan, chunk, text, "bench"));
      }
      store->Save(chunk, text);
    }
    state.PauseTiming();
    store->Remove();
    state.ResumeTiming();
  }
  Report(state, chunks.units);
}
void BM_RecordsAndStoreChunkPerUnit(benchmark::State& state) { IngestAndStore(state, true); }
void BM_ParseAndStoreChunkPerUnit(benchmark::State& state) { IngestAndStore(state, false); }
// Real time: writing files waits on the file system, not only on the CPU.
BENCHMARK(BM_RecordsAndStoreChunkPerUnit)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_ParseAndStoreChunkPerUnit)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
