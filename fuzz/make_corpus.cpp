// Writes the fuzz targets' seed corpora from the repository's tests and examples:
//   fuzz_make_corpus <source dir> <out dir>  ->  <out dir>/<target>/<seed files>
// Text targets get the files (and, for the command line, their lines); the image target gets
// the encoded images of every assembly case and every Gold example.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "bytecode/assembly.h"
#include "bytecode/image.h"
#include "dialects/registry.h"

namespace fs = std::filesystem;

namespace {

std::vector<fs::path> files_in(const fs::path& dir, const std::string& ext) {
  std::vector<fs::path> out;
  if (!fs::is_directory(dir)) return out;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file() && (ext.empty() || e.path().extension() == ext))
      out.push_back(e.path());
  return out;
}

std::string read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

class Corpus {
 public:
  Corpus(fs::path dir) : dir_(std::move(dir)) { fs::create_directories(dir_); }
  void add(const std::string& bytes) {
    if (!seen_.insert(bytes).second) return;
    std::ofstream(dir_ / ("seed_" + std::to_string(seen_.size())), std::ios::binary) << bytes;
  }
  size_t size() const { return seen_.size(); }

 private:
  fs::path dir_;
  std::set<std::string> seen_;
};

std::string as_string(const std::vector<uint8_t>& bytes) { return {bytes.begin(), bytes.end()}; }

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: fuzz_make_corpus <source dir> <out dir>\n");
    return 2;
  }
  const fs::path src = argv[1], out = argv[2];
  const auto gold_examples = files_in(src / "examples/gold", ".ehl");
  const auto gold_diagnostics = files_in(src / "tests/diagnostics/gold", ".gold");
  const auto preproc_cases = files_in(src / "tests/preproc/cases", ".case");
  std::vector<fs::path> asm_files = files_in(src / "tests/vm/cases", ".s");
  for (const auto& p : files_in(src / "tests/bytecode", ".s")) asm_files.push_back(p);
  for (const auto& p : files_in(src / "examples/asm", ".s")) asm_files.push_back(p);

  Corpus preproc(out / "fuzz_preproc"), compile(out / "fuzz_compile_gold"),
      line(out / "fuzz_gold_line"), image(out / "fuzz_image"),
      command_line(out / "fuzz_gold_command_line"), transcript(out / "fuzz_transcript"),
      transport(out / "fuzz_transport");
  for (const auto& p : preproc_cases) preproc.add(read(p));
  for (const auto& p : gold_examples) {
    preproc.add(read(p));
    compile.add(read(p));
  }
  for (const auto& p : gold_diagnostics) compile.add(read(p));
  // Command lines: the committed ones, and every line of the examples.
  for (const auto& p : files_in(src / "fuzz/corpus/fuzz_gold_line", "")) line.add(read(p));
  for (const auto& p : gold_examples) {
    std::istringstream lines(read(p));
    for (std::string l; std::getline(lines, l);)
      if (!l.empty() && l.size() < 200) line.add(l);
  }
  // Transcripts, and the lines they send for the command line.
  for (const auto& p : files_in(src / "tests/transcripts", ".txt")) {
    transcript.add(read(p));
    std::istringstream lines(read(p));
    for (std::string l; std::getline(lines, l);)
      if (l.size() > 2 && l.compare(0, 2, "> ") == 0) {
        command_line.add(l.substr(2));
        transport.add(std::string("\0\5", 2) + l.substr(2) + "\r\n");  // options, chunk, bytes
      }
  }
  for (const auto& p : files_in(src / "fuzz/corpus/fuzz_gold_line", "")) command_line.add(read(p));
  // Images.
  for (const auto& p : asm_files) {
    uprog::bytecode::Image img;
    std::vector<uprog::Diagnostic> errors;
    if (uprog::bytecode::assemble(read(p), p.filename().string(), img, errors))
      image.add(as_string(uprog::bytecode::encode(img)));
  }
  for (const auto& p : gold_examples) {
    // Gold's stored form is the encoded image; Gold is the registry's default dialect.
    const uprog::dialect::CompileOutput r = uprog::dialects::default_dialect().compile_source(
        uprog::SourceFile{p.filename().string(), read(p)}, {});
    if (r.ok()) image.add(as_string(r.stored_form));
  }
  std::printf(
      "seeds: fuzz_preproc %zu, fuzz_compile_gold %zu, fuzz_gold_line %zu, fuzz_image %zu, "
      "fuzz_gold_command_line %zu, fuzz_transcript %zu, fuzz_transport %zu\n",
      preproc.size(), compile.size(), line.size(), image.size(), command_line.size(),
      transcript.size(), transport.size());
  return 0;
}
