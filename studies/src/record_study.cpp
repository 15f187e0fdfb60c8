#include "anchorbench/studies/record_study.hpp"

#include "anchorbench/studies/exploration.hpp"
#include "anchorbench/studies/navigation.hpp"
#include "anchorbench/studies/pdop_study.hpp"

namespace anchorbench::studies {
namespace {

// One study's entry: its units (Units(config, components)), its check and its files' writer.
template <typename Record, typename Units, typename Check, typename Write>
RecordStudy Entry(std::string command, Units units, Check check, Write write_files,
                  std::function<std::uintmax_t(const schema::ExperimentConfig&)> result_bytes) {
  RecordStudy study;
  study.command = std::move(command);
  study.check = check;
  study.result_bytes = std::move(result_bytes);
  study.units = [units](const schema::ExperimentConfig& config, const registry::Components& components) {
    return units(config, components).units;
  };
  study.run = [units](const schema::ExperimentConfig& config, const registry::Components& components,
                      const engine::UnitComputing& computing, const engine::Shard& shard,
                      const engine::RunControl& control, engine::RecordJournal* journal) {
    return engine::RunUnitTexts(units(config, components), computing, shard, control, journal);
  };
  study.unit_text = [units](const schema::ExperimentConfig& config, const registry::Components& components) {
    return [study = units(config, components)](int unit) { return study.text(study.compute(unit)); };
  };
  study.write = [units, write_files](const engine::FileWriter& write, const schema::ExperimentConfig& config,
                                     const registry::Components& components, const std::map<int, std::string>& texts,
                                     const std::function<engine::UnitPlace(int)>& place_of, const report::RunInfo& info) {
    const std::vector<Record> records = engine::ReadUnitTexts(units(config, components), texts, place_of);
    return write_files(write, config, records, info);
  };
  return study;
}

// Lines of about `bytes_per_line` for each (row, realization) and each of `per_unit`, and the tables.
std::uintmax_t LinesOf(const schema::ExperimentConfig& config, std::size_t per_unit, std::uintmax_t bytes_per_line) {
  return bytes_per_line * static_cast<std::uintmax_t>(config.realizations) * schema::RowsOf(config).size() * per_unit +
         (1 << 16);
}

}  // namespace

const std::vector<RecordStudy>& RecordStudies() {
  static const std::vector<RecordStudy> studies = {
      Entry<NavigationRecord>("navigate", NavigationUnits, CheckNavigation, WriteNavigationFiles,
                              [](const schema::ExperimentConfig& config) {
                                return LinesOf(config, config.estimator.triggers.size() + 2, 150);
                              }),
      Entry<ExplorationRecord>("explore", ExplorationUnits, CheckExploration, WriteExplorationFiles,
                               [](const schema::ExperimentConfig& config) {
                                 return LinesOf(config, config.exploration->policies.size(), 120);
                               }),
      // A checkpoint line (~150 bytes) every `every` samples, a few thousand samples per anchor.
      Entry<schema::PdopStudy>("pdop-study", PdopStudyUnits, CheckPdopStudy, WritePdopStudyFiles,
                               [](const schema::ExperimentConfig& config) {
                                 const double anchors = static_cast<double>(config.realizations) *
                                                        config.scenario.NumAnchors();
                                 return static_cast<std::uintmax_t>(anchors * 150.0 * 5000.0 / PdopStudyOf(config).every) +
                                        (1 << 16);
                               }),
  };
  return studies;
}

const RecordStudy* FindRecordStudy(std::string_view command) {
  for (const RecordStudy& study : RecordStudies()) {
    if (study.command == command) return &study;
  }
  return nullptr;
}

}  // namespace anchorbench::studies
