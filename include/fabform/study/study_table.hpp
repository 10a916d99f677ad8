#pragma once
// DIR/study.csv: one row a case, its varied values, the figures the study collects, whether it
// converged, its termination, iterations and wall seconds. A case without a finished result is
// still a row, marked with how it ended (cancelled, timeout, failed, interrupted, missing),
// its figures empty.
#include <map>
#include <string>

#include <nlohmann/json.hpp>

#include "fabform/study/study_spec.hpp"

namespace fabform {

/// How the cases that ended without a finished result ended, by index; the others' rows come
/// from their result.json.
using CaseEndings = std::map<int, std::string>;

/// What a case's row shows: its finished result.json; null when it has none or ended otherwise.
nlohmann::json case_result(const std::string& dir, int index, const CaseEndings& endings);

/// A number as the table holds it: 17 significant digits, the very double of result.json.
std::string number_cell(const nlohmann::json& value);

/// RFC 4180: a cell with a comma, a quote or a line break is quoted, its quotes doubled.
std::string csv_cell(const std::string& text);

/// The table's text.
std::string study_table(const StudySpec& spec, const std::string& dir, const CaseEndings& endings);

/// Writes DIR/study.csv atomically; returns how many cases converged.
int write_study_table(const StudySpec& spec, const std::string& dir, const CaseEndings& endings);

}  // namespace fabform
