#include "scene/parameters.h"

#include "core/error.h"
#include "core/suggest.h"
#include "scene/scene.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace ib {

namespace {

using K = ParameterKind;
using I = Invalidates;

// A row of the table, said field by field.
class Row {
 public:
  Row(const char* name, const char* field, int component = -1) {
    spec_.name = name;
    spec_.field = field;
    spec_.component = component;
  }
  // A number in [lo, hi] (open at lo after openMin()), or a whole number, with its default.
  Row& number(double byDefault, double lo, double hi) { return kind(K::kNumber, byDefault, lo, hi); }
  Row& integer(double byDefault, double lo, double hi) { return kind(K::kInteger, byDefault, lo, hi); }
  Row& toggle(bool byDefault) { return kind(K::kToggle, byDefault ? 1 : 0, 0, 1); }
  Row& choice(int byDefault, std::vector<ParameterChoice> choices) {
    spec_.choices = std::move(choices);
    return kind(K::kChoice, byDefault, 0, double(spec_.choices.size()) - 1);
  }
  Row& color() { return kind(K::kColor, -1, -1, 0xffffff); }
  Row& openMin() { spec_.minOpen = true; return *this; }
  Row& zeroIsAuto() { spec_.zeroIsAuto = true; return *this; }
  Row& log() { spec_.logScale = true; return *this; }
  Row& unit(const char* unit) { spec_.unit = unit; return *this; }
  Row& meaning(const char* meaning) { spec_.meaning = meaning; return *this; }
  Row& invalidates(Invalidates what) { spec_.invalidates = what; return *this; }
  Row& live() { spec_.live = true; return *this; }
  Row& access(double (*get)(const Scene&), void (*set)(Scene&, double)) {
    spec_.get = get;
    spec_.set = set;
    return *this;
  }
  const ParameterSpec& spec() const { return spec_; }

 private:
  Row& kind(K kind, double byDefault, double lo, double hi) {
    spec_.kind = kind;
    spec_.defaultValue = byDefault;
    spec_.min = lo;
    spec_.max = hi;
    return *this;
  }
  ParameterSpec spec_;
};

// The table's rows, in the order of the docs. Defaults come from the option structs, whose own
// comments say why.
std::vector<ParameterSpec> makeTable() {
  const Scene scene;
  const InterpolationParams solver;
  const DynamicsParams dynamics;
  const TracingOptions tracing;
  const TimelineSettings timeline;
  std::vector<ParameterSpec> t;
  const auto add = [&t](const Row& row) { t.push_back(row.spec()); };

  // Meshing and tracing: a change builds the multimesh again.
  add(Row("edge_length", "edge_length").number(scene.edgeLength, 0.5, 1e6).zeroIsAuto().unit("px")
          .meaning("target edge length: no boundary edge and no edge of the reference mesh is longer; 0 follows the "
                   "drawings (sqrt(mean key area) / 16, in [1, 8] px)")
          .invalidates(I::kMultimesh)
          .access([](const Scene& s) { return s.edgeLength; }, [](Scene& s, double v) { s.edgeLength = v; }));
  add(Row("max_vertices", "max_vertices").integer(scene.maxVertices, 100, 1e9)
          .meaning("the size guard: a build whose estimated vertex count is larger stops before meshing, saying which "
                   "edge length fits")
          .invalidates(I::kNothing)
          .access([](const Scene& s) { return double(s.maxVertices); },
                  [](Scene& s, double v) { s.maxVertices = static_cast<int>(v); }));
  add(Row("corners", "corners")
          .choice(int(scene.corners), {{"paired", "corners every key has pair up like features"},
                                       {"vertices", "also a vertex at every other corner of every key"},
                                       {"off", "arc length between features only, as in the paper"}})
          .meaning("what the outlines' corners do to the correspondence").invalidates(I::kMultimesh)
          .access([](const Scene& s) { return double(s.corners); },
                  [](Scene& s, double v) { s.corners = static_cast<CornerHandling>(v); }));
  add(Row("correspondence", "correspondence")
          .choice(int(scene.correspondence), {{"outline", "arc length between features and corners, as in the paper"},
                                              {"artwork", "the outlines matched by position and tangent, and what is the same in every drawing stays still"}})
          .meaning("how the keys' outlines correspond between features").invalidates(I::kMultimesh)
          .access([](const Scene& s) { return double(s.correspondence); },
                  [](Scene& s, double v) { s.correspondence = static_cast<OutlineCorrespondence>(v); }));
  add(Row("tolerance", "tracing.tolerance").number(tracing.tolerance, 0, 10).openMin().unit("px")
          .meaning("potrace's curve tolerance and the flattening error of its curves").invalidates(I::kMultimesh)
          .access([](const Scene& s) { return s.tracing.tolerance; }, [](Scene& s, double v) { s.tracing.tolerance = v; }));
  add(Row("min_area", "tracing.min_area").number(tracing.minArea, 0, 1e9).unit("px^2")
          .meaning("pieces and holes smaller than this are specks and dropped").invalidates(I::kMultimesh)
          .access([](const Scene& s) { return s.tracing.minArea; }, [](Scene& s, double v) { s.tracing.minArea = v; }));
  add(Row("alpha_threshold", "tracing.alpha_threshold").integer(tracing.alphaThreshold, 1, 255)
          .meaning("with alpha, a pixel is shape when its alpha is at least this").invalidates(I::kMultimesh)
          .access([](const Scene& s) { return double(s.tracing.alphaThreshold); },
                  [](Scene& s, double v) { s.tracing.alphaThreshold = static_cast<int>(v); }));
  add(Row("paper_color", "tracing.background").color()
          .meaning("the paper colour [r, g, b]: drawings without alpha are traced by colour against it (white when "
                   "none is given), and every drawing when it is given")
          .invalidates(I::kMultimesh)
          .access(
              [](const Scene& s) {
                const auto& b = s.tracing.background;
                return b ? double((*b)[0] * 65536 + (*b)[1] * 256 + (*b)[2]) : -1.0;
              },
              [](Scene& s, double v) {
                const int c = static_cast<int>(v);
                if (c < 0) s.tracing.background.reset();
                else s.tracing.background = std::array<int, 3>{c >> 16, (c >> 8) & 255, c & 255};
              }));
  add(Row("color_threshold", "tracing.color_threshold").number(tracing.colorThreshold, 0, 442).openMin()
          .meaning("RGB distance from the paper colour above which a pixel is shape").invalidates(I::kMultimesh)
          .access([](const Scene& s) { return s.tracing.colorThreshold; },
                  [](Scene& s, double v) { s.tracing.colorThreshold = v; }));
  add(Row("holes", "tracing.holes")
          .choice(int(tracing.holes), {{"marked", "enclosed paper is shape unless a key's \"holes\" marks it"},
                                       {"enclosed-paper", "every enclosed paper region is a hole"}})
          .meaning("drawings on paper: which enclosed paper regions are holes").invalidates(I::kMultimesh)
          .access([](const Scene& s) { return double(s.tracing.holes); },
                  [](Scene& s, double v) { s.tracing.holes = static_cast<PaperHoles>(v); }));
  add(Row("kappa", "solver.kappa").number(scene.kappa, 0, 1e6).openMin().log()
          .meaning("stiffness of every triangle not painted otherwise (eq. 16), painted into the multimesh")
          .invalidates(I::kMultimesh)
          .access([](const Scene& s) { return s.kappa; }, [](Scene& s, double v) { s.kappa = v; }));

  // The solver: a change solves the frames again on the same multimesh.
  add(Row("lambda", "solver.lambda").number(solver.cohesive.lambda, 0, 1e12).log().unit("per normalized length")
          .meaning("cohesive stiffness (eq. 10): how hard glued cuts hold shut").live()
          .access([](const Scene& s) { return s.interpolation.cohesive.lambda; },
                  [](Scene& s, double v) { s.interpolation.cohesive.lambda = v; }));
  add(Row("tau", "solver.tau").number(solver.cohesive.tau, 0, 1e6).openMin().log().unit("normalized energy per pair")
          .meaning("cohesive threshold (eq. 11), cut_timing tau: a glued pair lets go when l/3 d exceeds it, lengths in shape sizes")
          .live()
          .access([](const Scene& s) { return s.interpolation.cohesive.tau; },
                  [](Scene& s, double v) { s.interpolation.cohesive.tau = v; }));
  add(Row("alpha", "solver.alpha").number(solver.cohesive.alpha, 0, 1)
          .meaning("glued pairs resist stretch across the cut (1) versus shear along it (0) (eq. 13)").live()
          .access([](const Scene& s) { return s.interpolation.cohesive.alpha; },
                  [](Scene& s, double v) { s.interpolation.cohesive.alpha = v; }));
  add(Row("non_overlap", "solver.non_overlap").toggle(solver.nonOverlap)
          .meaning("keep the shape from overlapping itself (W_O, eqs. 14-15)").live()
          .access([](const Scene& s) { return s.interpolation.nonOverlap ? 1.0 : 0.0; },
                  [](Scene& s, double v) { s.interpolation.nonOverlap = v != 0; }));
  add(Row("metric", "solver.metric")
          .choice(int(solver.metric), {{"shared", "one metric per triangle, no shrinking"}, {"per_key", "the paper's eq. 9"}})
          .meaning("how each triangle's keys are averaged (docs/solver.md, \"The shape metric\")").live()
          .access([](const Scene& s) { return double(s.interpolation.metric); },
                  [](Scene& s, double v) { s.interpolation.metric = static_cast<ShapeMetric>(v); }));

  // When cuts let go (docs/scene-format.md, "Cut timing"); each cut may give its own.
  add(Row("cut_timing", "solver.cut_timing")
          .choice(int(solver.cohesive.timing), {{"release", "by the weights: release and release_window"},
                                                 {"tau", "by the cohesive energy's threshold tau (the paper)"}})
          .meaning("what decides when a cut lets go (docs/solver.md, \"Cut timing\")").live()
          .access([](const Scene& s) { return double(s.interpolation.cohesive.timing); },
                  [](Scene& s, double v) { s.interpolation.cohesive.timing = static_cast<CutTiming>(v); }));
  add(Row("release", "solver.release").number(solver.cohesive.release, 0, 1)
          .meaning("the weight of the keys where a cut is open at the middle of its letting go (0.5: halfway between the keys)")
          .live()
          .access([](const Scene& s) { return s.interpolation.cohesive.release; },
                  [](Scene& s, double v) { s.interpolation.cohesive.release = v; }));
  add(Row("release_window", "solver.release_window").number(solver.cohesive.releaseWindow, 0, 1).openMin()
          .meaning("the span of that weight over which the sides part (or glue, on the way back)").live()
          .access([](const Scene& s) { return s.interpolation.cohesive.releaseWindow; },
                  [](Scene& s, double v) { s.interpolation.cohesive.releaseWindow = v; }));

  // The timeline's own fields (its marks are the scene's structure, not parameters).
  add(Row("fps", "timeline.fps").number(timeline.fps, 0, 1000).openMin().unit("frames/s")
          .meaning("frames per second: frames at start + f / fps")
          .access([](const Scene& s) { return s.timelineSettings.fps; },
                  [](Scene& s, double v) { s.timelineSettings.fps = v; }));
  add(Row("loop", "timeline.loop").toggle(timeline.loop)
          .meaning("the last mark repeats the first mark's pose and the frames stop before it")
          .access([](const Scene& s) { return s.timelineSettings.loop ? 1.0 : 0.0; },
                  [](Scene& s, double v) { s.timelineSettings.loop = v != 0; }));
  add(Row("spacing", "timeline.spacing")
          .choice(int(timeline.spacing), {{"weights", "equal steps of the weights"}, {"even", "equal steps of the shape"}})
          .meaning("every segment's spacing unless its mark says otherwise")
          .access([](const Scene& s) { return double(s.timelineSettings.spacing); },
                  [](Scene& s, double v) { s.timelineSettings.spacing = static_cast<SegmentSpacing>(v); }));

  // Dynamics: secondary motion, off while epsilon is 0.
  add(Row("epsilon", "dynamics.epsilon").number(dynamics.epsilon, 0, 1)
          .meaning("compliance: 0 follows the keys exactly (dynamics off), 1 allows the most secondary motion").live()
          .access([](const Scene& s) { return s.dynamics.epsilon; }, [](Scene& s, double v) { s.dynamics.epsilon = v; }));
  add(Row("gravity_x", "dynamics.gravity", 0).number(dynamics.gravity.x(), -100, 100).log().unit("shape sizes/s^2")
          .meaning("gravity, x (right)").live()
          .access([](const Scene& s) { return s.dynamics.gravity.x(); }, [](Scene& s, double v) { s.dynamics.gravity.x() = v; }));
  add(Row("gravity_y", "dynamics.gravity", 1).number(dynamics.gravity.y(), -100, 100).log().unit("shape sizes/s^2")
          .meaning("gravity, y (down)").live()
          .access([](const Scene& s) { return s.dynamics.gravity.y(); }, [](Scene& s, double v) { s.dynamics.gravity.y() = v; }));
  add(Row("wind_x", "dynamics.wind", 0).number(dynamics.wind.x(), -100, 100).log().unit("shape sizes/s^2")
          .meaning("wind, x (right)").live()
          .access([](const Scene& s) { return s.dynamics.wind.x(); }, [](Scene& s, double v) { s.dynamics.wind.x() = v; }));
  add(Row("wind_y", "dynamics.wind", 1).number(dynamics.wind.y(), -100, 100).log().unit("shape sizes/s^2")
          .meaning("wind, y (down)").live()
          .access([](const Scene& s) { return s.dynamics.wind.y(); }, [](Scene& s, double v) { s.dynamics.wind.y() = v; }));
  add(Row("gust", "dynamics.gust").number(dynamics.gust, 0, 1)
          .meaning("wind(s) = wind (1 + gust sin(2 pi gust_frequency s))").live()
          .access([](const Scene& s) { return s.dynamics.gust; }, [](Scene& s, double v) { s.dynamics.gust = v; }));
  add(Row("gust_frequency", "dynamics.gust_frequency").number(dynamics.gustFrequency, 0, 1000).openMin().log().unit("Hz")
          .meaning("how often the wind gusts").live()
          .access([](const Scene& s) { return s.dynamics.gustFrequency; },
                  [](Scene& s, double v) { s.dynamics.gustFrequency = v; }));
  add(Row("mu", "dynamics.mu").number(dynamics.mu, 0, 1e6).log().unit("1/s")
          .meaning("damping of the secondary motion (the force -mu M v)").live()
          .access([](const Scene& s) { return s.dynamics.mu; }, [](Scene& s, double v) { s.dynamics.mu = v; }));
  add(Row("anchor", "dynamics.anchor").number(dynamics.anchor, 0, 1e6).openMin().log()
          .meaning("how strongly the shape keeps to the animation, relative to its stiffness per vertex").live()
          .access([](const Scene& s) { return s.dynamics.anchor; }, [](Scene& s, double v) { s.dynamics.anchor = v; }));
  add(Row("settle", "dynamics.settle").number(dynamics.settle, 0, 1).openMin()
          .meaning("share of each segment's end over which dynamics fade out").live()
          .access([](const Scene& s) { return s.dynamics.settle; }, [](Scene& s, double v) { s.dynamics.settle = v; }));
  add(Row("max_deviation", "dynamics.max_deviation").number(dynamics.maxDeviation, 0, 100).openMin().log()
          .unit("shape sizes").meaning("the deviation budget at epsilon = 1").live()
          .access([](const Scene& s) { return s.dynamics.maxDeviation; },
                  [](Scene& s, double v) { s.dynamics.maxDeviation = v; }));

  // How the frames are drawn.
  add(Row("sampling", "sampling")
          .choice(int(scene.sampling), {{"auto", "nearest when every drawing is pixel art"},
                                        {"linear", "trilinear: smooth at any size"},
                                        {"nearest", "magnified pixel art keeps hard pixel edges"}})
          .meaning("how render, play and export filter the drawings' texels").invalidates(I::kNothing)
          .access([](const Scene& s) { return double(s.sampling); },
                  [](Scene& s, double v) { s.sampling = static_cast<ArtworkSampling>(v); }));

  add(Row("cut_ink", "cut_ink").toggle(scene.cutInk)
          .meaning("render, play and export draw the edges a cut opens with the drawings' outline ink, where they have one")
          .invalidates(I::kNothing)
          .access([](const Scene& s) { return s.cutInk ? 1.0 : 0.0; }, [](Scene& s, double v) { s.cutInk = v != 0; }));

  // The player's own: no scene field holds them.
  add(Row("kappa_scale", "").number(1, 1e-3, 1e3).log()
          .meaning("multiplies every triangle's stiffness against the cohesive pull; Save writes it into every "
                   "stiffness the scene names")
          .live());
  add(Row("dynamics", "").toggle(false)
          .meaning("secondary motion on or off, keeping epsilon (off saves epsilon 0)").live());
  return t;
}

std::string choiceList(const ParameterSpec& spec) {
  std::string list;
  for (size_t i = 0; i < spec.choices.size(); ++i) {
    if (i > 0) list += i + 1 == spec.choices.size() ? " or " : ", ";
    list += spec.choices[i].word;
  }
  return list;
}

}  // namespace

// 6 significant digits where they read back (0.001, not 0.0010000000000000000208), so a value
// written out and read again is the same value.
std::string shortestText(double value) {
  char text[32];
  for (int precision = 6; precision <= 17; ++precision) {
    std::snprintf(text, sizeof text, "%.*g", precision, value);
    if (std::strtod(text, nullptr) == value) break;
  }
  return text;
}

const std::vector<ParameterSpec>& parameterTable() {
  static const std::vector<ParameterSpec> table = makeTable();  // a constant, built once
  return table;
}

const ParameterSpec* findParameter(const std::string& name) {
  for (const ParameterSpec& spec : parameterTable()) {
    if (spec.name == name || (spec.component < 0 && !spec.field.empty() && spec.field == name)) return &spec;
    if (spec.component >= 0 && name == spec.field + (spec.component == 0 ? ".x" : ".y")) return &spec;
  }
  return nullptr;
}

const ParameterSpec& parameter(const std::string& name) {
  if (const ParameterSpec* spec = findParameter(name)) return *spec;
  std::vector<std::string> names;
  for (const ParameterSpec& spec : parameterTable()) {  // a name, or its field as the scene file spells it
    names.push_back(spec.name);
    if (!spec.field.empty()) names.push_back(spec.component < 0 ? spec.field : spec.field + (spec.component == 0 ? ".x" : ".y"));
  }
  throw InputError("unknown parameter " + inQuotes(name) + didYouMean(name, names) +
                   " (every parameter: `inbetween parameters`, docs/parameters.md)");
}

bool parameterValueValid(const ParameterSpec& spec, double value) {
  bool ok = std::isfinite(value);
  switch (spec.kind) {
    case K::kToggle: ok = ok && (value == 0 || value == 1); break;
    case K::kChoice: ok = ok && value == std::floor(value) && value >= 0 && value < double(spec.choices.size()); break;
    case K::kColor: ok = ok && value == std::floor(value) && (value == -1 || (value >= 0 && value <= 0xffffff)); break;
    case K::kInteger:
      ok = ok && value == std::floor(value) && value >= spec.min && value <= spec.max;
      break;
    case K::kNumber:
      ok = ok && ((spec.zeroIsAuto && value == 0) || ((spec.minOpen ? value > spec.min : value >= spec.min) && value <= spec.max));
      break;
  }
  return ok;
}

void checkParameterValue(const ParameterSpec& spec, double value, const std::string& where) {
  if (!parameterValueValid(spec, value))
    throw InputError(where + ": " + (std::isfinite(value) ? formatParameterValue(spec, value) : shortestText(value)) +
                     " is out of range " + formatParameterRange(spec));
}

double parseParameterText(const ParameterSpec& spec, const std::string& text, const std::string& where) {
  double value = 0;
  if (spec.kind == K::kToggle && (text == "on" || text == "true")) value = 1;
  else if (spec.kind == K::kToggle && (text == "off" || text == "false")) value = 0;
  else if (spec.kind == K::kColor && text == "none") value = -1;
  else if (spec.kind == K::kColor && text.size() == 6 && text.find_first_not_of("0123456789abcdefABCDEF") == std::string::npos)
    value = static_cast<double>(std::strtol(text.c_str(), nullptr, 16));
  else {
    bool found = false;
    for (size_t i = 0; i < spec.choices.size(); ++i)
      if (spec.choices[i].word == text) value = double(i), found = true;
    if (!found) {
      char* end = nullptr;
      value = std::strtod(text.c_str(), &end);
      if (text.empty() || end != text.c_str() + text.size() || spec.kind == K::kChoice || spec.kind == K::kColor) {
        std::string accepted = spec.kind == K::kChoice ? choiceList(spec)
                               : spec.kind == K::kColor ? "a colour RRGGBB or none"
                               : spec.kind == K::kToggle ? "on or off"
                                                         : "a number";
        std::vector<std::string> words;
        for (const ParameterChoice& c : spec.choices) words.push_back(c.word);
        throw InputError(where + ": " + inQuotes(text) + " is not " + accepted + didYouMean(text, words));
      }
    }
  }
  checkParameterValue(spec, value, where);
  return value;
}

std::string formatParameterValue(const ParameterSpec& spec, double value) {
  switch (spec.kind) {
    case K::kToggle:  // a value being refused is said as a number
      return value == 1 ? "on" : value == 0 ? "off" : shortestText(value);
    case K::kChoice:  // an index out of the list (a value being refused) is said as a number
      if (!(value >= 0 && value < double(spec.choices.size()) && value == std::floor(value))) return shortestText(value);
      return spec.choices[static_cast<size_t>(value)].word;
    case K::kColor: {
      if (value == -1) return "none";
      if (!(value >= 0 && value <= 0xffffff && value == std::floor(value))) return shortestText(value);
      char text[8];
      std::snprintf(text, sizeof text, "%06x", static_cast<int>(value));
      return text;
    }
    case K::kInteger:
    case K::kNumber: return shortestText(value);
  }
  return shortestText(value);
}

std::string formatParameterRange(const ParameterSpec& spec) {
  switch (spec.kind) {
    case K::kToggle: return "on or off";
    case K::kChoice: return choiceList(spec);
    case K::kColor: return "RRGGBB or none";
    case K::kInteger: return "whole numbers [" + shortestText(spec.min) + ", " + shortestText(spec.max) + "]";
    case K::kNumber: break;
  }
  const std::string range = (spec.minOpen ? "(" : "[") + shortestText(spec.min) + ", " + shortestText(spec.max) + "]";
  return spec.zeroIsAuto ? "0 (follow the drawings) or " + range : range;
}

}  // namespace ib
