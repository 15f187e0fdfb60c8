#include "anchorbench/studies/navigation_shard.hpp"

#include <map>
#include <sstream>

#include "anchorbench/studies/navigation_lines.hpp"
#include "anchorbench/io/csv_reader.hpp"
#include "anchorbench/io/hash.hpp"
#include "anchorbench/schema/input_error.hpp"

namespace anchorbench::studies {

using engine::ShardInfo;
using engine::ShardInputs;
using engine::WriteShardIdentity;
namespace {

// A line's checksum binds its fields to the run (the plan's identity): an edited value, a torn
// line or a line of another run's shard does not match.
std::string Checksum(const std::string& plan, std::string_view fields) {
  std::string text = plan;
  text.append("\n").append(fields);
  return io::Fingerprint(text);
}

}  // namespace

void WriteNavigationShard(const std::function<void(const std::string&, const std::string&)>& write,
                          const ShardInfo& info, const ShardInputs& inputs,
                          const std::vector<NavigationRecord>& records) {
  std::ostringstream csv;
  csv << kNavigationRecordColumns << ",checksum\n";
  for (const NavigationRecord& r : records) {
    const std::string fields = NavigationRecordFields(r);
    csv << fields << ',' << Checksum(info.plan, fields) << '\n';
  }
  write(kNavigationRecordsFile, csv.str());
  WriteShardIdentity(write, info, inputs);
}

std::vector<NavigationRecord> ReadNavigationShards(const std::vector<std::filesystem::path>& folders,
                                                   const std::vector<ShardInfo>& infos,
                                                   const schema::ExperimentConfig& config) {
  const std::vector<schema::RowConfig> row_configs = schema::RowsOf(config);
  const int rows = static_cast<int>(row_configs.size());
  const int units = rows * config.realizations;
  std::map<int, std::vector<NavigationRecord>> by_unit;
  for (std::size_t s = 0; s < folders.size(); ++s) {
    const std::string path = (folders[s] / kNavigationRecordsFile).string();
    std::ifstream in = io::OpenForReading(path);
    io::CsvReader csv(in, path);
    const NavigationRecordReader reader(csv);
    const int checksum = csv.Column({"checksum"});
    while (csv.Next()) {
      std::string_view fields = csv.record_text();
      fields = fields.substr(0, fields.rfind(','));
      if (csv.Text(checksum) != Checksum(infos[s].plan, fields)) {
        csv.Fail("the line does not match its checksum (edited after the run, or another run's?)");
      }
      NavigationRecord r = reader.Read(csv);
      const int unit = r.row * config.realizations + r.realization;
      if (r.row < 0 || r.row >= rows || r.realization < 0 || r.realization >= config.realizations ||
          !infos[s].shard.Holds(unit)) {
        csv.Fail("row " + std::to_string(r.row) + ", realization " + std::to_string(r.realization) +
                 " is not a unit of this shard (edited after the run?)");
      }
      by_unit[unit].push_back(std::move(r));
    }
  }
  std::vector<NavigationRecord> records;
  for (int unit = 0; unit < units; ++unit) {
    const auto found = by_unit.find(unit);
    std::vector<std::string> methods;
    if (found != by_unit.end()) {
      for (const NavigationRecord& r : found->second) methods.push_back(r.method);
    }
    if (methods != NavigationMethods(row_configs[static_cast<std::size_t>(unit / config.realizations)])) {
      throw schema::InputError("row " + std::to_string(unit / config.realizations) + ", realization " +
                               std::to_string(unit % config.realizations) + ": the shards' " + kNavigationRecordsFile +
                               " do not hold each of its methods once, in order (edited after the run?)");
    }
    for (NavigationRecord& r : found->second) records.push_back(std::move(r));
  }
  return records;
}

}  // namespace anchorbench::studies
