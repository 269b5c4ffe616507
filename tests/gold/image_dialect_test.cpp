// Every image the Gold compiler makes names its dialect: programs and the command line's tiny
// images alike, in the hosted Image and in the binary form a drive loads.
#include <gtest/gtest.h>

#include "bytecode/image_view.h"
#include "dialects/gold/compile.h"

namespace uprog::gold_test {
namespace {

std::string dialect_of_bytes(const bytecode::Image& image) {
  const std::vector<uint8_t> bytes = bytecode::encode(image);
  bytecode::ImageView view;
  EXPECT_EQ(bytecode::load_image(bytes.data(), bytes.size(), view), bytecode::LoadError::Ok);
  return view.dialect_name();
}

TEST(gold_image, ProgramsNameTheirDialect) {
  const gold::CompileResult r = gold::compile(SourceFile{"t.ehl", "int x\n##main\nx = 3\nexit\n"});
  ASSERT_TRUE(r.ok()) << format_text(r.diagnostics);
  EXPECT_EQ(r.image.dialect, "gold");
  EXPECT_EQ(dialect_of_bytes(r.image), "gold");
}

TEST(gold_image, CommandLineImagesNameTheirDialect) {
  const gold::CompiledLine c = gold::compile_line("3+4");
  ASSERT_TRUE(c.ok()) << format_text(c.diagnostics);
  EXPECT_EQ(c.image.dialect, "gold");
  EXPECT_EQ(dialect_of_bytes(c.image), "gold");
}

}  // namespace
}  // namespace uprog::gold_test
