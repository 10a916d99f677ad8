#pragma once
// A results folder changes all at once. A run's files are written into a staging folder beside
// it and then swapped in (one atomic exchange where the file system offers it), so the folder
// holds one run's complete files at every moment: the previous run's until the new ones are
// all written. A folder holding anything but fabform's results is never replaced.
#include <string>
#include <utility>
#include <vector>

namespace fabform {

/// A file of a results folder: its name and its bytes.
using ResultFile = std::pair<std::string, std::string>;

/// Checks, before a long solve, that `dir` can take results: it is new, empty, or an earlier
/// run's results folder (it holds result.json), and a small folder can be written beside it and
/// renamed into its place (then undone). Throws InputError naming the folder and what is wrong,
/// with the system's reason.
void check_results_folder(const std::string& dir);

/// Replaces the folder's content by exactly `files`, at once. Throws SystemError naming
/// the folder and the system's reason when it cannot; the folder then still holds what it held.
void publish_results(const std::string& dir, const std::vector<ResultFile>& files);

}  // namespace fabform
