#pragma once
// Content hashes a run records so that a rerun can tell whether its inputs changed: 64-bit FNV-1a
// (offset basis 14695981039346656037, prime 1099511628211) over the bytes, as 16 hex digits.
// Not a cryptographic hash: it detects edits, it does not resist forgery.
#include <filesystem>
#include <string>
#include <string_view>

namespace gcsim::pipeline {

// "fnv1a64:0123456789abcdef"
std::string content_hash(std::string_view bytes);
// The hash of a file's bytes; throws FileError when it cannot be read.
std::string file_content_hash(const std::filesystem::path& file);
// The hash of a machine file's content after inheritance (its `base` files laid under it), written
// out as TOML with sorted keys: two files that resolve to the same tables hash alike. An empty
// path is the built-in default machine.
std::string machine_content_hash(const std::string& machine_file);

}  // namespace gcsim::pipeline
