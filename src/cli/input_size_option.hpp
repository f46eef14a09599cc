// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The command's --max-input-size SIZE (issue 41, item 4): the limit on model files the user may
// raise explicitly (64 MiB by default, about 1.2 · 10⁶ bars of YAML), for every command that
// reads a model. The setting lives here, in the command, and reaches the library as options
// (io::ReadingLimits, io::ImportOptions::max_input_bytes).

#include <CLI/CLI.hpp>

#include <cstddef>
#include <optional>
#include <string_view>

#include "kinestat/io/yaml_support.hpp"

namespace kinestat::cli {

/// Bytes of a size written as a whole number and an optional unit, B or K, M, G, T with or
/// without "iB" (powers of 1024): "512MiB", "2G", "100000000". Nothing for 0, anything else,
/// or more than 1 TiB.
std::optional<std::size_t> parse_byte_size(std::string_view text);

/// Registers --max-input-size SIZE on `command`.
void add_input_size_option(CLI::App& command);

/// The limits on model files --max-input-size gives: its bytes, and the parsed nodes of a YAML
/// file in proportion (2^24 nodes per 64 MiB, the defaults' ratio); the defaults without it.
io::ReadingLimits model_reading_limits();

}  // namespace kinestat::cli
