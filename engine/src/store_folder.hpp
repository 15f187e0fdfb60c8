#pragma once
// Where a job keeps its finished work until its results are written: the folder <out>.chunks/
// beside the result folder, with `plan.csv` naming the job (its identity). The chunk store (one
// file per chunk) and the record journal (one file appended to) both claim it here, the same way:
// internal to the engine.

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "anchorbench/engine/chunk_store.hpp"

namespace anchorbench::engine {

// `folder` claimed for the job `identity` before any work: refused if it holds one of `inputs`
// or anything a store does not write; in kFresh mode refused if it holds an interrupted job's
// work (`held()` describes it: "12 finished chunks"); in kResume refused if it is another job's;
// discarded in kOverwrite, or when killed before its plan file was in place. True: created empty
// (write the plan file once the rest is set up); false: an earlier store of this job, kept.
// `ours(name)` says which file names the store writes besides its plan file. Errors are
// schema::InputError naming the folder and the way out.
bool ClaimStoreFolder(const std::filesystem::path& folder, const std::string& identity, ChunkStore::Mode mode,
                      const std::vector<std::filesystem::path>& inputs, const std::function<bool(const std::string&)>& ours,
                      const std::function<std::string()>& held);

// plan.csv: identity, chunks and units (whole or absent).
void WriteStorePlan(const std::filesystem::path& folder, const std::string& identity, long long chunks, long long units);

}  // namespace anchorbench::engine
