#pragma once
// DIR/study_specimens.csv: a study with specimens (StudySpec::specimens) as a drape tester reports
// it (BS 5058 and ISO 9073-9 test several specimens and give their mean): one row a case, the
// range of its specimens' rows in study.csv ("cases", e.g. 4-7), its varied values without the
// seed, how many specimens finished and converged, and for every figure the mean, the sample
// standard deviation (n − 1), the least and the largest over the specimens that converged and
// have it: a run stopped short is no reading.
#include <string>

#include "fabform/study/study_table.hpp"

namespace fabform {

/// The table's text; a figure no converged specimen of a case has is empty in its row.
std::string specimen_summary(const StudySpec& spec, const std::string& dir, const CaseEndings& endings);

/// Writes DIR/study_specimens.csv atomically.
void write_specimen_summary(const StudySpec& spec, const std::string& dir, const CaseEndings& endings);

}  // namespace fabform
