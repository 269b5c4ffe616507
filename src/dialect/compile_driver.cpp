// The one compile driver of every dialect: a source file read whole, then the dialect's front end
// over it in memory (Dialect::compile_source), so that a file and a text in memory (an editor's
// buffer, a fuzzer's input, a test's program) compile the same way.
#include "dialect/dialect.h"
#include "support/files.h"

namespace uprog::dialect {

CompileOutput Dialect::compile_file(const std::string& path,
                                    const CompileSettings& settings) const {
  std::string why;
  std::optional<std::string> text = read_text_file(path, &why);
  if (!text) {
    CompileOutput out;
    out.diagnostics.push_back(unreadable_source(path, why));
    return out;
  }
  return compile_source(SourceFile{path, std::move(*text)}, settings);
}

}  // namespace uprog::dialect
