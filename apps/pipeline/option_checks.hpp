#pragma once
// Checks that every command's options share: numbers must be finite (CLI11 reads "nan", "inf" and
// "1e400" as doubles, and a Range check lets NaN through), byte counts must not be negative.
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace gcsim::pipeline {

// Adds to every option of app and its subcommands, recursively, a check that each value (and each
// item of a comma-separated list) that reads as a number in full is a finite one.
void reject_non_finite_numbers(CLI::App* app);

// For a byte count with unit suffixes (CLI::AsSizeValue): add with ->transform() AFTER the
// AsSizeValue transform, so that it runs first and "-1KB" fails with a clear message instead of
// wrapping around to 18446744073709551615.
CLI::Validator no_negative_size();

// A positive, finite number (e.g. --exposure, whose absence means automatic).
CLI::Validator positive_number();

// --scene NAME: a built-in name (case-insensitive) passes; a name that looks like a path (has a
// '/' or a '.') must be an existing file, else FileError "... does not exist". Other names are left
// to the application, whose message lists its built-in scenes.
void check_scene_file(const std::string& name, const std::vector<std::string>& builtins);

}  // namespace gcsim::pipeline
