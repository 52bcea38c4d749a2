// `vahf check FILE` (and the Python module's vahf.check): validates a scene,
// experiment, lab dataset, override or synthetic-lab generator file as a run
// would before its first trial, and says what it holds.
#pragma once

#include <string>

namespace vahf::kinds {

// What the file holds, ending with "PATH: valid KIND\n"; an InputError naming
// file, JSON pointer, value and rule when it is not valid.
std::string CheckFile(const std::string& path);

}  // namespace vahf::kinds
