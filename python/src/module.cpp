// catena._core: the Python binding of the library's entry point (catena/catena.hpp) and its case
// runner (catena/io/case_run.hpp). Values cross as text, exactly as on the command line; the
// conversion of Python values to that text, and the public API, live in python/catena/.
// The GIL is released while a model runs.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <future>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "catena/catena.hpp"
#include "catena/io/atomic_file.hpp"
#include "catena/io/bind.hpp"
#include "catena/io/case_file.hpp"
#include "catena/io/case_run.hpp"
#include "catena/io/quantity.hpp"
#include "catena/io/record.hpp"
#include "catena/io/report.hpp"
#include "catena/io/sha256.hpp"
#include "catena/sweep.hpp"

namespace catena::cli {
std::string_view plotly_js();  // embedded web/node_modules/plotly.js-dist-min/plotly.min.js
}

namespace py = pybind11;

namespace {

// The ident of Python's main thread, the only one that runs signal handlers (set at import).
unsigned long main_thread_ident = 0;

// Runs `work(cancel)` with the GIL released. On Python's main thread it runs on a thread of its
// own while this one waits, checking for signals every 50 ms (PyErr_CheckSignals): a Ctrl-C
// (KeyboardInterrupt, or whatever a Python signal handler raised) sets `cancel`, the run stops
// at its next poll (catena/core/progress.hpp), and the exception is raised once it has stopped:
// no result. On another thread (a pool's worker) no signal can arrive: it runs right here.
template <class Work>
auto interruptible(Work work) -> decltype(work(nullptr)) {
  if (PyThread_get_thread_ident() != main_thread_ident) {
    py::gil_scoped_release release;
    return work(nullptr);
  }
  std::atomic<bool> cancel{false};
  auto future = std::async(std::launch::async, [&work, &cancel] { return work(&cancel); });
  for (;;) {
    {
      py::gil_scoped_release release;
      if (future.wait_for(std::chrono::milliseconds(50)) == std::future_status::ready) break;
    }
    if (PyErr_CheckSignals() != 0) {
      cancel.store(true);
      {
        py::gil_scoped_release release;
        future.wait();
      }
      try {
        (void)future.get();  // Cancelled, or a result that came in the meantime: dropped
      } catch (...) {
      }
      throw py::error_already_set();
    }
  }
  return future.get();
}

// A Progress that only listens for `cancel` (nullptr: nobody listens).
catena::Progress cancel_only(const std::atomic<bool>* cancel) {
  catena::Progress progress;
  progress.cancel = cancel;
  return progress;
}

using catena::analysis::Analysis;
using catena::analysis::Parameter;
using catena::analysis::ParameterType;
using catena::analysis::Record;
using catena::analysis::Value;
using Texts = std::vector<std::pair<std::string, std::string>>;

const char* type_name(ParameterType type) {
  switch (type) {
    case ParameterType::kQuantity:
      return "quantity";
    case ParameterType::kNumber:
      return "number";
    case ParameterType::kInteger:
      return "integer";
    case ParameterType::kChoice:
      return "choice";
    case ParameterType::kFlag:
      return "flag";
    case ParameterType::kText:
      return "text";
    case ParameterType::kTable:
      return "table";
  }
  return "text";
}

py::dict parameter_dict(const Parameter& p) {
  py::dict d;
  d["name"] = p.name;
  d["type"] = type_name(p.type);
  d["kind"] = p.type == ParameterType::kQuantity ? py::object(py::str(kind_name(p.kind)))
                                                 : py::object(py::none());
  d["unit"] = catena::io::bare_unit(p);
  d["required"] = p.required;
  d["default"] = p.default_text.empty() ? py::object(py::none()) : py::str(p.default_text);
  d["list"] = p.list;
  d["choices"] = p.choices;
  d["example"] = p.example.empty() ? py::object(py::none()) : py::str(p.example);
  d["doc"] = p.doc;
  d["cli_only"] = p.cli_only;
  d["aliases"] = p.aliases;
  py::list fields;
  for (const Parameter& f : p.fields) fields.append(parameter_dict(f));
  for (const Parameter& f : p.row_fields) {
    py::dict fd = parameter_dict(f);
    fd["name"] = p.rows_name + "." + f.name;
    fields.append(fd);
  }
  d["fields"] = fields;
  return d;
}

py::dict analysis_dict(const Analysis& a) {
  py::dict d;
  d["name"] = a.name;
  d["command"] = a.command;
  d["title"] = a.title;
  d["help"] = a.help;
  d["seed"] = a.seed;
  d["docs"] = a.docs;
  d["chain_types"] = a.chain_types;
  d["example"] = a.example_doc.empty() ? py::object(py::none()) : py::str(a.example_doc);
  py::list params;
  for (const Parameter& p : a.parameters) params.append(parameter_dict(p));
  d["parameters"] = params;
  return d;
}

// The JSON tree as Python objects: the values `--format json` prints (a non-finite real is
// null there, None here).
py::object to_python(const Value& v) {
  if (v.is_null()) return py::none();
  if (v.is_bool()) return py::bool_(v.as_bool());
  if (v.is_integer()) return py::int_(v.as_integer());
  if (v.is_real()) {
    const double x = v.as_number();
    return std::isfinite(x) ? py::object(py::float_(x)) : py::object(py::none());
  }
  if (v.is_string()) return py::str(v.as_string());
  if (v.is_array()) {
    py::list out;
    for (const Value& e : v.as_array()) out.append(to_python(e));
    return out;
  }
  py::dict out;
  for (const auto& [key, member] : v.as_object()) out[py::str(key)] = to_python(member);
  return out;
}

py::list issues_list(const std::vector<catena::Issue>& issues) {
  py::list out;
  for (const catena::Issue& i : issues) {
    out.append(py::make_tuple(i.field, i.value, i.expected, catena::to_string(i)));
  }
  return out;
}

py::list diagnostics_list(const std::vector<catena::Diagnostic>& diagnostics) {
  py::list out;
  for (const catena::Diagnostic& d : diagnostics) {
    py::dict e;
    e["severity"] = catena::to_string(d.severity);
    e["code"] = d.code;
    e["message"] = d.message;
    e["value"] = d.value;
    e["limit"] = d.limit;
    out.append(e);
  }
  return out;
}

// One analysis run: its name, its inputs as text and the Record.
struct Result {
  std::string name;
  Texts inputs;
  Record record;
};

// A case file run.
struct Case {
  catena::io::CaseRun run;
};

// The value at a dotted path of the tree ("series.vx"); nullptr when absent.
const Value* at_path(const Value& root, const std::string& path) {
  const Value* v = &root;
  std::size_t start = 0;
  while (v != nullptr && start <= path.size()) {
    const std::size_t dot = path.find('.', start);
    const std::string key = path.substr(start, dot == std::string::npos ? dot : dot - start);
    v = v->find(key);
    if (dot == std::string::npos) break;
    start = dot + 1;
  }
  return v;
}

py::array_t<double> series(const Result& r, const std::string& path) {
  const Value* v = at_path(r.record.data, path);
  if (v == nullptr) throw py::key_error("no '" + path + "' in the result of " + r.name);
  if (!v->is_array())
    throw py::type_error("'" + path + "' of the result of " + r.name + " is not a list");
  for (const Value& e : v->as_array()) {
    if (!e.is_number() && !e.is_null())
      throw py::type_error("'" + path + "' of the result of " + r.name +
                           " is not a list of numbers");
  }
  const std::vector<double> values = v->numbers();
  py::array_t<double> out(static_cast<py::ssize_t>(values.size()));
  std::copy(values.begin(), values.end(), out.mutable_data());
  return out;
}

// A report from analysis runs made in Python: the inputs table lists each run's values as typed.
catena::io::Report results_report(const std::vector<const Result*>& results,
                                  const std::string& title) {
  catena::io::Report report;
  report.title = title;
  report.case_name = "python";
  report.version = CATENA_VERSION;
  std::vector<catena::io::AnalysisRun> runs;
  std::string all_inputs;
  for (const Result* r : results) {
    const Analysis* a = catena::find_analysis(r->name);
    std::string id = r->name;
    int n = 1;
    for (const auto& run : runs) {
      if (run.name == id) id = r->name + "-" + std::to_string(++n);
    }
    for (const auto& [key, text] : r->inputs) {
      const Parameter* p = a->parameter(key);
      const std::string unit =
          p != nullptr && catena::io::is_bare_number(text) ? catena::io::bare_unit(*p) : "";
      report.inputs.push_back({id + "." + key, text, unit});
      all_inputs += id + "." + key + " = " + text + "\n";
    }
    runs.push_back({a, id, r->record});
  }
  report.case_hash = catena::io::sha256_hex(all_inputs);
  report.sections = catena::io::report_sections(runs);
  return report;
}

}  // namespace

PYBIND11_MODULE(_core, m) {
  m.doc() = "Catena's C++ library (use the catena package, not this module)";
  m.attr("__version__") = CATENA_VERSION;
  main_thread_ident =
      py::module_::import("threading").attr("main_thread")().attr("ident").cast<unsigned long>();

  // InputError crosses as (issues) through this exception; python/catena/__init__.py raises
  // catena.InputError from it.
  static py::exception<catena::InputError> input_error(m, "_InputError", PyExc_ValueError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const catena::InputError& e) {
      py::gil_scoped_acquire gil;
      py::object error = py::handle(input_error.ptr())(py::str(e.what()));
      error.attr("issues") = issues_list(e.issues());
      PyErr_SetObject(input_error.ptr(), error.ptr());
    } catch (const catena::io::WriteError& e) {
      PyErr_SetString(PyExc_OSError, e.what());
    } catch (const catena::Cancelled& e) {  // interruptible() raises the signal's own error
      PyErr_SetString(PyExc_KeyboardInterrupt, e.what());
    }
  });

  m.def("analyses", [] {
    py::list out;
    for (const Analysis* a : catena::analyses()) out.append(analysis_dict(*a));
    return out;
  });

  // Binds without running: the binder's problems (for a front end that found problems of its own
  // and lists them together).
  m.def("bind_issues", [](const std::string& name, const Texts& inputs) {
    const Analysis* a = catena::find_analysis(name);
    if (a == nullptr) return issues_list({{"analysis", name, "an analysis Catena has"}});
    std::vector<catena::io::RawInput> raw;
    for (const auto& [key, text] : inputs) {
      const Parameter* p = a->parameter(key);
      const bool is_flag = p && p->type == ParameterType::kFlag;
      raw.push_back(
          {key,
           text,
           is_flag ? catena::io::RawInput::Type::kBoolean : catena::io::RawInput::Type::kText,
           {},
           {}});
    }
    std::vector<catena::Issue> issues;
    catena::io::bind(*a, raw, issues);
    return issues_list(issues);
  });

  py::class_<Result, std::shared_ptr<Result>>(m, "Result")
      .def_readonly("name", &Result::name)
      .def_readonly("inputs", &Result::inputs)
      .def("to_dict", [](const Result& r) { return to_python(r.record.data); })
      .def("to_json", [](const Result& r) { return catena::io::to_json(r.record.data); })
      .def("diagnostics", [](const Result& r) { return diagnostics_list(r.record.diagnostics); })
      .def("table", [](const Result& r) { return r.record.table; })
      .def("series", &series);

  m.def("run", [](const std::string& name, const Texts& inputs) {
    auto r = std::make_shared<Result>();
    r->name = name;
    r->inputs = inputs;
    r->record = interruptible([&](const std::atomic<bool>* cancel) {
      const catena::Progress progress = cancel_only(cancel);
      return catena::run(name, inputs, cancel != nullptr ? &progress : nullptr);
    });
    return r;
  });

  // A chunk of a sweep: explicit input sets (the package merges grid and base), run on the
  // library's thread pool with the GIL released. Returns (columns, units, rows): the scalar
  // results, then the worst diagnostic's severity and code, then the input error ("" when the
  // point ran); NaN where a point lacks a result. The inputs' columns are the package's.
  // A whole sweep's problems before it is split into chunks (Dask): its keys, a table's file,
  // the total work over every point (catena::sweep_points); nothing runs.
  m.def("check_sweep", [](const std::string& name, const std::vector<Texts>& sets) {
    catena::SweepRequest request;
    request.analysis = name;
    request.points = sets;
    std::vector<catena::Issue> issues;
    catena::share_table_files(request, issues);
    catena::throw_if_any(issues);
    catena::sweep_points(request);
  });

  m.def("sweep", [](const std::string& name, const std::vector<Texts>& sets, unsigned threads) {
    catena::SweepRequest request;
    request.analysis = name;
    request.points = sets;
    // a point naming a value inside its table (dynamics.sprocket[1].load_torque): the table's
    // file read once, each point's value put in place of the file's
    std::vector<catena::Issue> issues;
    catena::share_table_files(request, issues);
    catena::throw_if_any(issues);
    catena::SweepOptions options;
    options.threads = threads;
    options.keep_records = false;
    const catena::SweepTable table = interruptible([&](const std::atomic<bool>* cancel) {
      catena::SweepOptions own = options;
      own.cancel = cancel;
      return catena::sweep_table(catena::sweep(request, own));
    });
    py::list columns;
    py::list units;
    for (const auto& r : table.results) {
      columns.append(r.name);
      units.append(r.unit);
    }
    for (const auto* t : {&table.severity, &table.code, &table.error}) {
      columns.append(t->name);
      units.append("");
    }
    py::list rows;
    for (std::size_t i = 0; i < table.rows(); ++i) {
      py::list row;
      for (const auto& r : table.results) row.append(r.values[i]);
      for (const auto* t : {&table.severity, &table.code, &table.error}) row.append(t->values[i]);
      rows.append(py::tuple(row));
    }
    return py::make_tuple(columns, units, rows);
  });

  py::class_<Case, std::shared_ptr<Case>>(m, "Case")
      .def_property_readonly("name", [](const Case& c) { return c.run.file.name; })
      .def("to_dict",
           [](const Case& c) { return to_python(catena::io::result_tree(c.run, CATENA_VERSION)); })
      .def("results", [](const Case& c) {
        py::list out;
        for (const catena::io::AnalysisRun& r : c.run.runs) {
          auto result = std::make_shared<Result>();
          result->name = r.analysis->name;
          result->record = r.record;
          out.append(py::make_tuple(r.name, result));
        }
        return out;
      });

  m.def("run_case", [](const std::string& path) {
    auto c = std::make_shared<Case>();
    c->run = interruptible([&](const std::atomic<bool>* cancel) {
      const catena::Progress progress = cancel_only(cancel);
      return catena::io::run_case(catena::io::read_case(path),
                                  cancel != nullptr ? &progress : nullptr);
    });
    return c;
  });

  m.def("report_case", [](const Case& c, const std::string& path) {
    py::gil_scoped_release release;
    catena::io::write_file_atomic(
        path, catena::io::to_html(catena::io::build_report(c.run, CATENA_VERSION),
                                  catena::cli::plotly_js()));
  });

  m.def("report_results", [](const std::vector<std::shared_ptr<Result>>& results,
                             const std::string& path, const std::string& title) {
    std::vector<const Result*> rs;
    for (const auto& r : results) rs.push_back(r.get());
    const catena::io::Report report = results_report(rs, title);
    py::gil_scoped_release release;
    catena::io::write_file_atomic(path, catena::io::to_html(report, catena::cli::plotly_js()));
  });
}
