#pragma once

#include <string>
#include <vector>

namespace rise::cli {

// `rise studio [SCENE] [--script FILE]` runs RISE Studio, the program
// rise-studio built beside this one, in this process's place. Returns only
// when it cannot: the exit status, the reason printed.
int startStudio(const std::vector<std::string>& arguments);

}  // namespace rise::cli
