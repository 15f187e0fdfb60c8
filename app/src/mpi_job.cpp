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
#include "anchorbench/studies/record_study.hpp"

namespace anchorbench::app {
namespace {

// Rank 0 -> worker: kPlan (the experiments' texts and their identity), kStart (a Compute begins:
// threads, and the study of record units whose units it computes, or none for the plan's chunks;
// the worker's threads, each on its own, ask for items), kStop. A worker thread -> rank 0: kReady
// (its thread number) or kResult, also a request for the next: thread, item and, for a chunk, its
// text and its records (rank 0 stores the text and reads the records, parsing no text), for a
// unit its text; kError (exit code and message). Rank 0 -> a worker thread: kChunkFor + thread
// (an item's index, or empty: no more for this Compute).
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
  HandOut(plan, "", chunks, threads, [&](std::vector<std::string>& fields, const std::string& rank) {
    const int chunk = std::stoi(fields.at(1));
    done(chunk, engine::FromRecords(plan, chunk, fields.at(2), fields.at(3), rank + "'s chunk " + fields[1]),
         fields[2]);
  });
}

void MpiExecutor::ComputeUnits(const engine::UnitWork& work, const std::vector<int>& units, int threads,
                               const engine::UnitDone& done) {
  if (ranks_ == 1 || units.empty()) return local_.ComputeUnits(work, units, threads, done);
  HandOut(*work.plan, work.study, units, threads, [&](std::vector<std::string>& fields, const std::string&) {
    done(std::stoi(fields.at(1)), std::move(fields.at(2)));
  });
}

void MpiExecutor::HandOut(const engine::Plan& plan, const std::string& study, const std::vector<int>& items,
                          int threads, const Take& take) {
  busy_ = true;
  std::vector<std::string> message = {plan.identity()};
  message.insert(message.end(), plan.texts().begin(), plan.texts().end());
  const std::string packed = Pack(message);
  for (int rank = 1; rank < ranks_; ++rank) {
    if (packed != plan_sent_) Send(rank, kPlan, packed);
    Send(rank, kStart, Pack({std::to_string(threads), study}));
  }
  plan_sent_ = packed;
  // Every worker thread asks for an item, and for the next with each result, until told no more.
  std::size_t next = 0, received = 0;
  int told_no_more = 0;
  const int asking = (ranks_ - 1) * threads;
  while (received < items.size() || told_no_more < asking) {
    MPI_Status status;
    const std::string text = Receive(MPI_ANY_SOURCE, MPI_ANY_TAG, status);
    engine::ThrowIfStopped(stop_);  // busy_ stays set: Finish aborts the workers mid-plan
    const std::string rank = "rank " + std::to_string(status.MPI_SOURCE);
    if (status.MPI_TAG == kError) {
      if (text.rfind("2", 0) == 0) throw schema::InputError(rank + ": " + text.substr(1));
      throw std::runtime_error(rank + ": " + text.substr(1));
    }
    std::vector<std::string> fields = Unpack(text);  // thread [, item, its result's texts]
    if (status.MPI_TAG == kResult) {
      take(fields, rank);
      ++received;
    }
    const int reply_tag = kChunkFor + std::stoi(fields[0]);
    if (next < items.size()) {
      Send(status.MPI_SOURCE, static_cast<Tag>(reply_tag), std::to_string(items[next++]));
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

// One worker thread: asks for an item (a chunk or a unit), computes it, sends its result's texts
// (asking for the next), until rank 0 says no more. Errors go to rank 0, which ends the job.
void ServeThread(const std::function<std::vector<std::string>(int item)>& compute, int thread) {
  std::string request = Pack({std::to_string(thread)});
  Tag tag = kReady;
  for (;;) {
    Send(0, tag, request);
    MPI_Status status;
    const std::string item_text = Receive(0, kChunkFor + thread, status);
    if (item_text.empty()) return;
    try {
      std::vector<std::string> result = compute(std::stoi(item_text));
      result.insert(result.begin(), {std::to_string(thread), item_text});
      request = Pack(result);
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
        plan_error = e.what();  // reported for the first item asked of it
      }
      continue;
    }
    const std::vector<std::string> start = Unpack(text);  // kStart: threads, the study (none: chunks)
    std::string error = plan ? "" : plan_error;
    std::function<std::string(int)> unit_text;
    if (plan && !start[1].empty()) {
      try {  // reported, like a plan's error, for the first unit asked of it
        const studies::RecordStudy* study = studies::FindRecordStudy(start[1]);
        if (!study) throw schema::InputError("'" + start[1] + "' is not a study of record units");
        unit_text = study->unit_text(plan->experiments().front(), components_);
      } catch (const std::exception& e) {
        error = e.what();
      }
    }
#pragma omp parallel num_threads(std::stoi(start[0]))
    {
      std::vector<estimator::RangeSample> samples;  // this thread's, reused from chunk to chunk
      ServeThread([&](int item) -> std::vector<std::string> {
        if (!error.empty()) throw schema::InputError(error);
        if (unit_text) return {unit_text(item)};
        const engine::ChunkResult result = engine::ComputeChunk(*plan, item, components_, samples, &InterruptFlag());
        return {engine::ChunkText(*plan, item, result), engine::ChunkRecords(*plan, item, result)};
      }, omp_get_thread_num());
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
