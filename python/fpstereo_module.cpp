// The Python module `fpstereo`: the golden model (the hardware's exact output) on numpy images,
// the configuration as the command-line tools resolve it, the Verilog and dataset evaluation.
// docs/python.md describes it; tests/python/test_fpstereo.py checks it against `fpstereo run`.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <opencv2/core.hpp>

#include "config.hpp"
#include "dataset.hpp"
#include "files.hpp"
#include "golden_model.hpp"
#include "image_io.hpp"
#include "metrics.hpp"
#include "pair_eval.hpp"
#include "rtl_emitter.hpp"

namespace py = pybind11;

namespace fpstereo {
namespace {

// A keyword argument as the text its command-line flag would carry: True/False as on/off, a list
// (paths) comma-separated, anything else as str() gives it; the parameter table parses the text.
std::string flag_text(const py::handle& value) {
  if (py::isinstance<py::bool_>(value)) return value.cast<bool>() ? "on" : "off";
  if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
    std::string joined;
    for (const auto& item : value) joined += (joined.empty() ? "" : ",") + py::str(item).cast<std::string>();
    return joined;
  }
  return py::str(value).cast<std::string>();
}

// An 8-bit image as numpy holds it: gray (H, W), or colour (H, W, 3) BGR / (H, W, 4) BGRA as
// cv2.imread gives it, converted to gray as `fpstereo run` converts a colour file.
GrayImage gray_from_array(const py::handle& object, const std::string& role) {
  if (!py::isinstance<py::array>(object))
    throw InputError(role + ": expected a numpy array, got " + py::str(py::type::of(object)).cast<std::string>());
  const auto array = py::reinterpret_borrow<py::array>(object);
  if (!array.dtype().is(py::dtype::of<uint8_t>()))
    throw InputError(role + ": dtype " + py::str(array.dtype()).cast<std::string>() + ", expected uint8");
  const bool colour = array.ndim() == 3 && (array.shape(2) == 3 || array.shape(2) == 4);
  if (array.ndim() != 2 && !colour)
    throw InputError(role + ": shape " + py::str(array.attr("shape")).cast<std::string>() +
                     ", expected (height, width), (height, width, 3) or (height, width, 4)");
  if (array.shape(0) == 0 || array.shape(1) == 0) throw InputError(role + ": the image is empty");
  const auto contiguous = py::array_t<uint8_t, py::array::c_style>::ensure(array);
  const int channels = colour ? int(array.shape(2)) : 1;
  const cv::Mat image(int(array.shape(0)), int(array.shape(1)), CV_8UC(channels),
                      const_cast<uint8_t*>(contiguous.data()));
  return to_gray_image(image, role);
}

template <class T>
py::array_t<T> to_array(const Image<T>& image) {
  py::array_t<T> array({image.height, image.width});
  std::copy(image.pixels.begin(), image.pixels.end(), array.mutable_data());
  return array;
}

py::array_t<float> to_array(const cv::Mat1f& disparity) {
  py::array_t<float> array({disparity.rows, disparity.cols});
  for (int y = 0; y < disparity.rows; ++y)
    std::copy(disparity[y], disparity[y] + disparity.cols, array.mutable_data(y, 0));
  return array;
}

py::dict counts_dict(const std::optional<ErrorCounts>& counts) {
  py::dict d;
  if (!counts) return d;
  d["gt_pixels"] = counts->gt_pixels;
  d["density_percent"] = counts->density_percent();
  d["d1_percent"] = counts->d1_percent();
  d["bad1_percent"] = counts->bad1_percent();
  d["bad2_percent"] = counts->bad2_percent();
  d["bad4_percent"] = counts->bad4_percent();
  d["mae_px"] = counts->mae_px();
  return d;
}

// The pipeline of one configuration, resolved and validated when constructed.
class StereoSGM {
 public:
  StereoSGM(const std::optional<std::string>& preset_name, const py::kwargs& params) {
    std::map<std::string, std::string> values;
    for (const auto& [key, value] : params) {
      std::string name = key.cast<std::string>();
      std::replace(name.begin(), name.end(), '_', '-');  // p2_adapt is the flag --p2-adapt
      values[name] = flag_text(value);
    }
    cfg_ = compose_config(preset_name, "", values);
    validate(cfg_);
  }

  // Every plane the configuration outputs (gen/core/outputs.hpp), by name.
  py::dict compute_words(const py::handle& left, const py::handle& right) const {
    py::dict out;
    for (const auto& [plane, words] : run(left, right, output_planes(cfg_)))
      out[py::str(plane_info(plane).name)] = to_array(words);
    return out;
  }

  // Disparities in pixels, NaN where invalid: the values `fpstereo run --pfm` writes.
  py::array_t<float> compute(const py::handle& left, const py::handle& right) const {
    return to_array(to_float_disparity(run(left, right, {Plane::Disparity}).at(Plane::Disparity), cfg_));
  }

  py::dict config() const {
    py::dict d;
    for (const auto& spec : param_specs()) d[py::str(spec.name)] = spec.get(cfg_);
    return d;
  }

  std::string verilog() const { return rtl::emit_single_file(rtl::plan(cfg_)); }

  // Accuracy on every pair of a dataset folder (pairs.csv), as `fpstereo eval` scores it:
  // per pair and pooled, on the valid pixels and after KITTI's background fill.
  py::dict evaluate(const std::string& dataset_dir) const {
    std::vector<PairInputs> inputs;
    for (const auto& pair : read_pairs_csv(dataset_dir)) inputs.push_back(load_pair(pair, cfg_));
    py::dict pairs;
    Scores all_valid, all_filled;  // pooled as `fpstereo eval` pools: from the first pair on
    for (size_t i = 0; i < inputs.size(); ++i) {
      const PairInputs& in = inputs[i];
      const cv::Mat1f est = to_float_disparity(run_golden(in.cfg, in.left, in.right), in.cfg);
      const Scores valid = score(est, in), filled = score(kitti_fill(est), in);
      if (i == 0) {
        all_valid = valid, all_filled = filled;
      } else {
        pool(all_valid.occ, valid.occ), pool(all_valid.noc, valid.noc);
        pool(all_filled.occ, filled.occ), pool(all_filled.noc, filled.noc);
      }
      pairs[py::str(in.pair.name)] = scores_dict(valid, filled);
    }
    py::dict result;
    result["pairs"] = pairs;
    result["all"] = scores_dict(all_valid, all_filled);
    return result;
  }

  std::string repr() const { return "fpstereo.StereoSGM(" + config_tag(cfg_) + ")"; }

 private:
  Planes run(const py::handle& left, const py::handle& right, const std::vector<Plane>& planes) const {
    const GrayImage l = gray_from_array(left, "left image"), r = gray_from_array(right, "right image");
    check_pair(l, r, cfg_);
    py::gil_scoped_release unlocked;  // the images are copied: other Python threads may run
    return run_golden(cfg_, l, r, planes);
  }

  static py::dict scores_dict(const Scores& valid, const Scores& filled) {
    py::dict d;
    d["occ"] = counts_dict(valid.occ);
    d["noc"] = counts_dict(valid.noc);
    d["occ_filled"] = counts_dict(filled.occ);
    d["noc_filled"] = counts_dict(filled.noc);
    return d;
  }

  StereoConfig cfg_;
};

}  // namespace
}  // namespace fpstereo

PYBIND11_MODULE(fpstereo, m) {
  using namespace fpstereo;
  m.doc() = "fpstereo: the SGM pipeline's golden model, bit-exact with the generated hardware";
  start_image_codecs();  // its registry built on import, not in a later decode (image_io.hpp)
  // The CLIs' bad-input errors, one line each, as ValueError ("invalid config: ..." like the CLI).
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const ConfigError& e) {
      PyErr_SetString(PyExc_ValueError, (std::string("invalid config: ") + e.what()).c_str());
    } catch (const InputError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const FileError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    }
  });
  m.def("preset_names", &preset_names, "the named configurations StereoSGM(preset=...) takes");
  m.def(
      "load_gray", [](const std::string& path) { return to_array(load_gray(path, "image")); }, py::arg("path"),
      "an image file as the 8-bit gray array `fpstereo run` reads from it");
  py::class_<StereoSGM>(m, "StereoSGM")
      .def(py::init<const std::optional<std::string>&, const py::kwargs&>(), py::arg("preset") = py::none(),
           "a pipeline configuration: a preset (C2 when none), then parameters named as the command-line "
           "flags with _ for - (p2_adapt=4, lr='lr1', paths=[0, 90], gap_interp=True)")
      .def("compute", &StereoSGM::compute, py::arg("left"), py::arg("right"),
           "disparities in pixels (float32, NaN where invalid) of uint8 images, gray or BGR(A)")
      .def("compute_words", &StereoSGM::compute_words, py::arg("left"), py::arg("right"),
           "the raw planes the configuration outputs (uint16), by name: 'disparity' (the output words) and the others configured")
      .def("config", &StereoSGM::config, "every parameter's value, as text")
      .def("verilog", &StereoSGM::verilog, "the pipeline in Verilog, one file (fpstereo-rtl's output)")
      .def("evaluate", &StereoSGM::evaluate, py::arg("dataset_dir"),
           "accuracy on a dataset folder with pairs.csv, per pair and pooled")
      .def("__repr__", &StereoSGM::repr);
}
