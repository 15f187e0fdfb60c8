#include "mpi_job.hpp"

#include <mpi.h>

#include <chrono>
#include <iostream>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "anchorbench/io/input_error.hpp"

namespace anchorbench::app {
namespace {

// Rank 0 -> worker: kPlan (threads, identity, the experiments' texts), kWork (chunk indices),
// kStop. Worker -> rank 0: kResult (chunk index, chunk text), kError (exit code, message).
enum Tag : int { kPlan = 1, kWork, kStop, kResult, kError };

void Send(int rank, Tag tag, const std::string& text) {
  MPI_Send(text.data(), static_cast<int>(text.size()), MPI_CHAR, rank, tag, MPI_COMM_WORLD);
}

// The next message from `source` (or any), waited for by polling: a blocking receive would spin a
// core that the ranks computing beside it need.
std::string Receive(int source, MPI_Status& status) {
  for (int arrived = 0;;) {
    MPI_Iprobe(source, MPI_ANY_TAG, MPI_COMM_WORLD, &arrived, &status);
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

void MpiExecutor::Compute(const work::Plan& plan, const std::vector<int>& chunks, int threads,
                          const work::ChunkDone& done) {
  if (ranks_ == 1 || chunks.empty()) return local_.Compute(plan, chunks, threads, done);
  busy_ = true;
  std::vector<std::string> message = {std::to_string(threads), plan.identity()};
  message.insert(message.end(), plan.texts().begin(), plan.texts().end());
  const std::string packed = Pack(message);
  if (packed != plan_sent_) {
    for (int rank = 1; rank < ranks_; ++rank) Send(rank, kPlan, packed);
    plan_sent_ = packed;
  }
  std::size_t next = 0;
  std::vector<int> outstanding(static_cast<std::size_t>(ranks_), 0);
  const auto hand_out = [&](int rank) {  // as many chunks as the rank has threads
    std::vector<std::string> batch;
    for (; next < chunks.size() && static_cast<int>(batch.size()) < threads; ++next) {
      batch.push_back(std::to_string(chunks[next]));
    }
    outstanding[static_cast<std::size_t>(rank)] = static_cast<int>(batch.size());
    if (!batch.empty()) Send(rank, kWork, Pack(batch));
  };
  for (int rank = 1; rank < ranks_; ++rank) hand_out(rank);
  for (std::size_t received = 0; received < chunks.size(); ++received) {
    MPI_Status status;
    const std::string text = Receive(MPI_ANY_SOURCE, status);
    const std::string rank = "rank " + std::to_string(status.MPI_SOURCE);
    if (status.MPI_TAG == kError) {
      if (text.rfind("2", 0) == 0) throw io::InputError(rank + ": " + text.substr(1));
      throw std::runtime_error(rank + ": " + text.substr(1));
    }
    const std::size_t newline = text.find('\n');
    const int chunk = std::stoi(text.substr(0, newline));
    const std::string chunk_text = text.substr(newline + 1);
    done(chunk, work::ParseChunk(plan, chunk, chunk_text, rank + "'s chunk " + std::to_string(chunk)), chunk_text);
    if (--outstanding[static_cast<std::size_t>(status.MPI_SOURCE)] == 0) hand_out(status.MPI_SOURCE);
  }
  busy_ = false;
}

int MpiJob::Init(int& argc, char**& argv, int& rank) {
  int provided = 0;
  // Worker threads send their finished chunks one at a time (an OpenMP critical section).
  MPI_Init_thread(&argc, &argv, MPI_THREAD_SERIALIZED, &provided);
  int ranks = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  if (provided < MPI_THREAD_SERIALIZED) {
    if (rank == 0) std::cerr << "anchorbench: error: this MPI library cannot send from OpenMP threads\n";
    MPI_Abort(MPI_COMM_WORLD, 3);
  }
  return ranks;
}

MpiJob::MpiJob(int& argc, char**& argv, const registry::Components& components)
    : components_(components), ranks_(Init(argc, argv, rank_)), executor_(components, ranks_) {}

int MpiJob::Serve() {
  work::LocalExecutor local(components_);
  std::optional<work::Plan> plan;
  std::string plan_error;
  int threads = 1;
  for (;;) {
    MPI_Status status;
    const std::string text = Receive(0, status);
    if (status.MPI_TAG == kStop) break;
    try {
      if (status.MPI_TAG == kPlan) {
        const std::vector<std::string> message = Unpack(text);
        threads = std::stoi(message[0]);
        plan.reset();
        plan_error.clear();
        try {
          plan.emplace(work::PlanFromTexts({message.begin() + 2, message.end()}, message[1], components_));
        } catch (const io::InputError& e) {
          plan_error = e.what();  // reported for the first chunk asked of it
        }
        continue;
      }
      if (!plan) throw io::InputError(plan_error.empty() ? "chunks asked before a plan" : plan_error);
      std::vector<int> chunks;
      for (const std::string& chunk : Unpack(text)) chunks.push_back(std::stoi(chunk));
      local.Compute(*plan, chunks, threads, [](int chunk, work::ChunkResult&&, const std::string& chunk_text) {
        Send(0, kResult, std::to_string(chunk) + '\n' + chunk_text);
      });
    } catch (const io::InputError& e) {
      Send(0, kError, std::string("2") + e.what());
    } catch (const std::exception& e) {
      Send(0, kError, std::string("3") + e.what());
    }
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
