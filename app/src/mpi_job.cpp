#include "mpi_job.hpp"

#include <mpi.h>
#include <omp.h>

#include <chrono>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <thread>

#include "interrupt.hpp"

#include "anchorbench/schema/input_error.hpp"

namespace anchorbench::app {
namespace {

// Rank 0 -> worker: kPlan (the experiments' texts and their identity), kStart (a Compute begins:
// the worker's threads, each on its own, ask for chunks), kStop. A worker thread -> rank 0: kReady
// (its thread number) or kResult (thread, chunk index, chunk text, the chunk's records: also a
// request for the next; rank 0 stores the text and reads the records, parsing no text),
// kError (exit code and message). Rank 0 -> a worker thread: kChunkFor + thread (a chunk index,
// or empty: no more for this Compute).
enum Tag : int { kPlan = 1, kStart, kStop, kReady, kResult, kError, kChunkFor = 100 };

void Send(int rank, Tag tag, const std::string& text) {
  MPI_Send(text.data(), static_cast<int>(text.size()), MPI_CHAR, rank, tag, MPI_COMM_WORLD);
}

// The next message from `source` (or any) with `tag` (or any), waited for by polling: a blocking
// receive would spin a core that the threads computing beside it need.
std::string Receive(int source, int tag, MPI_Status& status) {
  for (int arrived = 0;;) {
    MPI_Iprobe(source, tag, MPI_COMM_WORLD, &arrived, &status);
    if (arrived) break;
    std::this_thread::sleep_for(std::chrono::microseconds(500));
  }
  int size = 0;
  MPI_Get_count(&status, MPI_CHAR, &size);
  std::string text(static_cast<std::size_t>(size), '\0');
  MPI_Recv(text.data(), size, MPI_CHAR, status.MPI_SOURCE, status.MPI_TAG, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  return text;
}

// Texts with their lengths, so that any byte may be in them.
std::string Pack(const std::vector<std::string>& texts) {
  std::string packed;
  for (const std::string& text : texts) packed += std::to_string(text.size()) + '\n' + text;
  return packed;
}

std::vector<std::string> Unpack(const std::string& packed) {
  std::vector<std::string> texts;
  for (std::size_t at = 0; at < packed.size();) {
    const std::size_t newline = packed.find('\n', at);
    const std::size_t size = std::stoul(packed.substr(at, newline - at));
    texts.push_back(packed.substr(newline + 1, size));
    at = newline + 1 + size;
  }
  return texts;
}

}  // namespace

void MpiExecutor::Compute(const engine::Plan& plan, const std::vector<int>& chunks, int threads,
                          const engine::ChunkDone& done) {
  if (ranks_ == 1 || chunks.empty()) return local_.Compute(plan, chunks, threads, done);
  busy_ = true;
  std::vector<std::string> message = {plan.identity()};
  message.insert(message.end(), plan.texts().begin(), plan.texts().end());
  const std::string packed = Pack(message);
  for (int rank = 1; rank < ranks_; ++rank) {
    if (packed != plan_sent_) Send(rank, kPlan, packed);
    Send(rank, kStart, std::to_string(threads));
  }
  plan_sent_ = packed;
  // Every worker thread asks for a chunk, and for the next with each result, until told no more.
  std::size_t next = 0, received = 0;
  int told_no_more = 0;
  const int asking = (ranks_ - 1) * threads;
  while (received < chunks.size() || told_no_more < asking) {
    MPI_Status status;
    const std::string text = Receive(MPI_ANY_SOURCE, MPI_ANY_TAG, status);
    engine::ThrowIfStopped(stop_);  // busy_ stays set: Finish aborts the workers mid-plan
    const std::string rank = "rank " + std::to_string(status.MPI_SOURCE);
    if (status.MPI_TAG == kError) {
      if (text.rfind("2", 0) == 0) throw schema::InputError(rank + ": " + text.substr(1));
      throw std::runtime_error(rank + ": " + text.substr(1));
    }
    const std::vector<std::string> fields = Unpack(text);  // thread [, chunk, chunk text, records]
    if (status.MPI_TAG == kResult) {
      const int chunk = std::stoi(fields[1]);
      done(chunk, engine::FromRecords(plan, chunk, fields[2], fields[3], rank + "'s chunk " + std::to_string(chunk)),
           fields[2]);
      ++received;
    }
    const int reply_tag = kChunkFor + std::stoi(fields[0]);
    if (next < chunks.size()) {
      Send(status.MPI_SOURCE, static_cast<Tag>(reply_tag), std::to_string(chunks[next++]));
    } else {
      Send(status.MPI_SOURCE, static_cast<Tag>(reply_tag), "");
      ++told_no_more;
    }
  }
  busy_ = false;
}

int MpiJob::Init(int& argc, char**& argv, int& rank) {
  int provided = 0;
  // A worker's threads each ask rank 0 for chunks and send results on their own.
  MPI_Init_thread(&argc, &argv, MPI_THREAD_MULTIPLE, &provided);
  int ranks = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  if (provided < MPI_THREAD_MULTIPLE) {
    if (rank == 0) std::cerr << "anchorbench: error: this MPI library cannot send from OpenMP threads\n";
    MPI_Abort(MPI_COMM_WORLD, 3);
  }
  return ranks;
}

MpiJob::MpiJob(int& argc, char**& argv, const registry::Components& components)
    : components_(components), ranks_(Init(argc, argv, rank_)), executor_(components, ranks_, &InterruptFlag()) {}

// One worker thread: asks for a chunk, computes it, sends it (asking for the next), until rank 0
// says no more. Errors go to rank 0, which ends the job.
void ServeThread(const engine::Plan* plan, const std::string& plan_error, int thread,
                 const registry::Components& components) {
  std::vector<estimator::RangeSample> samples;
  std::string request = Pack({std::to_string(thread)});
  Tag tag = kReady;
  for (;;) {
    Send(0, tag, request);
    MPI_Status status;
    const std::string chunk_text = Receive(0, kChunkFor + thread, status);
    if (chunk_text.empty()) return;
    const int chunk = std::stoi(chunk_text);
    try {
      if (!plan) throw schema::InputError(plan_error);
      const engine::ChunkResult result = engine::ComputeChunk(*plan, chunk, components, samples, &InterruptFlag());
      request = Pack({std::to_string(thread), chunk_text, engine::ChunkText(*plan, chunk, result),
                      engine::ChunkRecords(*plan, chunk, result)});
      tag = kResult;
    } catch (const schema::InputError& e) {
      request = std::string("2") + e.what();
      tag = kError;
    } catch (const std::exception& e) {
      request = std::string("3") + e.what();
      tag = kError;
    }
  }
}

int MpiJob::Serve() {
  std::optional<engine::Plan> plan;
  std::string plan_error;
  for (;;) {
    MPI_Status status;
    const std::string text = Receive(0, MPI_ANY_TAG, status);
    if (status.MPI_TAG == kStop) break;
    if (status.MPI_TAG == kPlan) {
      const std::vector<std::string> message = Unpack(text);
      plan.reset();
      plan_error = "no plan";
      try {
        plan.emplace(engine::PlanFromTexts({message.begin() + 1, message.end()}, message[0], components_));
      } catch (const std::exception& e) {
        plan_error = e.what();  // reported for the first chunk asked of it
      }
      continue;
    }
    const int threads = std::stoi(text);  // kStart
    const engine::Plan* computing = plan ? &*plan : nullptr;
#pragma omp parallel num_threads(threads)
    ServeThread(computing, plan_error, omp_get_thread_num(), components_);
  }
  MPI_Finalize();
  return 0;
}

int MpiJob::Finish(int exit_code) {
  if (executor_.busy()) MPI_Abort(MPI_COMM_WORLD, exit_code == 0 ? 3 : exit_code);
  for (int rank = 1; rank < ranks_; ++rank) Send(rank, kStop, "");
  MPI_Finalize();
  return exit_code;
}

}  // namespace anchorbench::app
