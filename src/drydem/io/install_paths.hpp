// SPDX-License-Identifier: MIT
// Where the files DryDEM ships beside its executable live (the Python scripts it starts, the
// examples): found at run time from the executable's own place, so that no path into the source
// checkout is compiled in and an installed tree runs anywhere.
//   $DRYDEM_DATA_DIR                  when set (a frozen copy of the binary, a relocated tree)
//   <exe dir>/share/drydem            the build tree (CMake links it to the sources)
//   <exe dir>/../share/drydem         an installed tree (cmake --install, the Debian package)
#pragma once
#include <filesystem>
#include <string_view>

namespace drydem {

/// The first of the folders above that exists; empty when none does.
std::filesystem::path data_dir();

/// data_dir()/scripts/<name>; InputError naming the places looked at when it is not there.
std::filesystem::path script_path(std::string_view name);

} // namespace drydem
