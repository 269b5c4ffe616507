// Test support: a Gold source text compiled to the bytes a host downloads.
#pragma once
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "bytecode/image.h"
#include "dialects/gold/compile.h"

namespace uprog::controller {

inline std::vector<uint8_t> compile_bytes(const std::string& text) {
  SourceFile source;
  source.name = "test.ehl";
  source.text = text;
  gold::CompileResult r = gold::compile(source);
  EXPECT_TRUE(r.ok()) << format_text(r.diagnostics);
  return bytecode::encode(r.image);
}

}  // namespace uprog::controller
