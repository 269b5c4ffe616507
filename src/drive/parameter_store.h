// Non-volatile parameter storage (SV/LD): Parameters as a text file with one "NAME[n]=value" line
// each and a CRC-32 trailer, written atomically; a corrupt or truncated file is refused.
#pragma once
#include <optional>
#include <string>

#include "drive/parameters.h"

namespace uprog::drive {

std::string serialize_parameters(const Parameters& params);
// nullopt (with `error` set) when the CRC does not match or a line cannot be parsed.
std::optional<Parameters> parse_parameters(const std::string& text, std::string* error = nullptr);

// SV: false with `error` set when the file could not be written; the old one is then intact.
bool save_parameters(const Parameters& params, const std::string& path,
                     std::string* error = nullptr);
// LD: nullopt when the file is missing or corrupt; the caller keeps its parameters.
std::optional<Parameters> load_parameters(const std::string& path, std::string* error = nullptr);

}  // namespace uprog::drive
