// The in-process simulated drive for Python (`uprog._uprog.Core`, wrapped by uprog.SimDrive): a
// pybind11 module over the controller, in virtual time, with the recorder as numpy arrays.
// It re-implements nothing: lines, time, the world and the recorder are the controller's and
// the transcript runner's (src/transcript/recording_options.h).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "controller/controller.h"
#include "dialects/registry.h"
#include "drive/axis.h"
#include "drive/faults.h"
#include "drive/recorder.h"
#include "transcript/recording_options.h"

namespace py = pybind11;

namespace uprog::python {
namespace {

constexpr int kInputs = 6;  // the drive's digital inputs (the transcripts' `input`, `switch`)

py::list answers_of(const std::vector<controller::Answer>& answers) {
  py::list out;
  for (const controller::Answer& a : answers) out.append(py::make_tuple(a.text, a.error));
  return out;
}

py::dict diagnostic_of(const Diagnostic& d) {
  py::dict out;
  out["file"] = d.where.file;
  out["line"] = d.where.line;
  out["column"] = d.where.column;
  out["code"] = d.code;
  out["message"] = d.message;
  out["severity"] = d.severity == Severity::Error     ? "error"
                    : d.severity == Severity::Warning ? "warning"
                                                      : "note";
  return out;
}

const dialect::Dialect& dialect_named(const std::string& name) {
  const dialect::Dialect* d = dialects::find(name);
  if (d == nullptr) throw py::value_error("no dialect named '" + name + "' (uprog dialects)");
  return *d;
}

void check_input(int n) {
  if (n < 1 || n > kInputs) throw py::value_error("inputs are numbered 1 to 6");
}

// One drive with one host session on its command line; the log kept until Python takes it.
class Core {
 public:
  Core(const std::string& dialect, uint32_t axes, const std::string& state_dir, bool safe_boot,
       uint32_t servo_period_us) {
    if (axes < 1 || axes > controller::kMaxAxes) throw py::value_error("axes are 1 to 4");
    if (servo_period_us != 0 &&
        (servo_period_us < drive::kMinPeriod_us || servo_period_us > drive::kMaxPeriod_us))
      throw py::value_error("servo_period_us is 25 to 2000");
    controller::ControllerOptions o;
    o.dialect = &dialect_named(dialect);
    o.axes = axes;
    o.state_dir = state_dir;
    o.safe_boot = safe_boot;
    o.servo_period_us = servo_period_us;
    drive_ = std::make_unique<controller::Controller>(o);
    host_ = drive_->open_session();
  }

  std::string dialect() const { return std::string(drive_->dialect().name()); }
  std::vector<std::string> boot_messages() const { return drive_->boot_messages(); }

  // Compiles and downloads (diagnostics, warnings included, and whether it was stored).
  py::tuple download(const std::string& path) {
    std::vector<Diagnostic> diagnostics;
    const bool ok = drive_->download_source_file(path, diagnostics);
    py::list out;
    for (const Diagnostic& d : diagnostics) out.append(diagnostic_of(d));
    return py::make_tuple(ok, out);
  }
  // Stores a stored form as it is (a .upi image, a .cup file): "" or why the drive refused it.
  std::string download_stored(const py::bytes& stored) {
    const std::string bytes = stored;
    const dialect::DownloadResult r =
        drive_->download(std::vector<uint8_t>(bytes.begin(), bytes.end()));
    return r.ok ? std::string() : (r.error.empty() ? "refused" : r.error);
  }
  std::string stored_extension() const { return std::string(drive_->dialect().stored_extension()); }
  std::string load_line() const { return drive_->dialect().load_line(); }

  py::list send(const std::string& line) { return answers_of(host_->send(line)); }
  py::list query(const std::string& line) { return answers_of(drive_->query(line)); }

  // Lets up to `us` of virtual time pass in steps of `step_us`, stopping after the step in which
  // the program hit a run-time error; the time that passed.
  uint64_t advance(uint64_t us, uint64_t step_us) {
    step_us = std::max<uint64_t>(step_us, 1);
    uint64_t passed = 0;
    while (passed < us) {
      const uint64_t step = std::min(step_us, us - passed);
      drive_->advance(step);
      passed += step;
      if (take_log_into_buffer()) break;
    }
    return passed;
  }
  uint64_t now_us() const { return drive_->now_us(); }
  uint32_t servo_period_us() { return drive_->axis().period_us(); }

  void set_input(int n, bool high) {
    check_input(n);
    drive_->set_input_level(n, high);
  }
  void place_switch(int n, double from_counts, double to_counts) {
    check_input(n);
    if (!(from_counts <= to_counts)) throw py::value_error("a switch needs lo <= hi");
    drive_->axis().place_position_switch(n, from_counts, to_counts);
  }
  void inject_fault(const std::string& name, bool persistent) {
    if (!drive_->inject_fault(name, persistent)) {
      std::string known;
      for (const drive::FaultName& f : drive::fault_names())
        known += (known.empty() ? "" : ", ") + std::string(f.name);
      throw py::value_error("no fault named '" + name + "' (" + known + ")");
    }
  }

  bool program_running() const { return drive_->program_running(); }
  int32_t program_error() const { return drive_->program_error(); }
  std::string program_error_text() const { return drive_->program_error_text(); }
  // The log since the last call: (time_us, text) each.
  std::vector<std::pair<uint64_t, std::string>> take_log() {
    take_log_into_buffer();
    return std::exchange(log_, {});
  }
  std::vector<std::string> take_output() { return drive_->take_output(); }

  void record(const std::string& channels, const std::string& trigger, uint32_t pretrigger,
              uint32_t length, uint32_t gap) {
    transcript::RecordRequest request;
    request.channels = channels;
    request.trigger = trigger;
    request.pretrigger_percent = pretrigger;
    request.length = length;
    request.gap_cycles = gap;
    request.early_trigger = true;  // as `uprog run`: a BG right after the start is caught
    if (pretrigger > 100) throw py::value_error("pretrigger is 0 to 100 (percent)");
    if (length == 0 || gap == 0) throw py::value_error("length and gap are 1 or more");
    drive::RecorderSettings settings;
    if (const std::string why = transcript::recorder_settings(*drive_, request, settings);
        !why.empty())
      throw py::value_error(why);
    if (std::string why; !drive_->recorder().arm(settings, &why)) throw py::value_error(why);
  }

  // The finished recording, or None: its header and (name, unit, is_float, values) per channel.
  py::object recording() {
    const auto r = drive_->recorder().recording(drive_->axis().period_us());
    if (!r) return py::none();
    py::dict out;
    out["sample_period_us"] = r->sample_period_us;
    out["trigger"] = r->trigger;
    out["pretrigger_percent"] = r->pretrigger_percent;
    out["trigger_index"] = r->trigger_index;
    out["trigger_time_us"] = r->trigger_time_us;
    py::list channels;
    for (const drive::RecordedChannel& c : r->channels) {
      py::array_t<double> values(static_cast<py::ssize_t>(c.values.size()));
      std::copy(c.values.begin(), c.values.end(), values.mutable_data());
      channels.append(py::make_tuple(c.name, c.unit, c.is_float, values));
    }
    out["channels"] = channels;
    return out;
  }

 private:
  // True when a run-time error came with this batch of the log.
  bool take_log_into_buffer() {
    bool error = false;
    for (dialect::LogEntry& e : drive_->take_log()) {
      error = error || e.text.find("run-time error") != std::string::npos;
      log_.emplace_back(e.time_us, std::move(e.text));
    }
    return error;
  }

  std::unique_ptr<controller::Controller> drive_;
  std::unique_ptr<dialect::Session> host_;
  std::vector<std::pair<uint64_t, std::string>> log_;
};

}  // namespace
}  // namespace uprog::python

PYBIND11_MODULE(_uprog, m) {
  using uprog::python::Core;
  m.doc() = "uprog's simulated drive in process (wrapped by uprog.SimDrive)";
  m.def("dialects", [] {
    std::vector<std::string> names;
    for (const auto* d : uprog::dialects::all()) names.emplace_back(d->name());
    return names;
  });
  py::class_<Core>(m, "Core")
      .def(py::init<const std::string&, uint32_t, const std::string&, bool, uint32_t>(),
           py::arg("dialect"), py::arg("axes") = 1, py::arg("state_dir") = "",
           py::arg("safe_boot") = false, py::arg("servo_period_us") = 0)
      .def_property_readonly("dialect", &Core::dialect)
      .def("boot_messages", &Core::boot_messages)
      .def("download", &Core::download)
      .def("download_stored", &Core::download_stored)
      .def("stored_extension", &Core::stored_extension)
      .def("load_line", &Core::load_line)
      .def("send", &Core::send)
      .def("query", &Core::query)
      .def("advance", &Core::advance, py::arg("us"), py::arg("step_us"))
      .def("now_us", &Core::now_us)
      .def("servo_period_us", &Core::servo_period_us)
      .def("set_input", &Core::set_input)
      .def("place_switch", &Core::place_switch)
      .def("inject_fault", &Core::inject_fault, py::arg("name"), py::arg("persistent") = false)
      .def("program_running", &Core::program_running)
      .def("program_error", &Core::program_error)
      .def("program_error_text", &Core::program_error_text)
      .def("take_log", &Core::take_log)
      .def("take_output", &Core::take_output)
      .def("record", &Core::record)
      .def("recording", &Core::recording);
}
