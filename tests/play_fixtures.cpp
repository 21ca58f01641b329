#include "play_fixtures.h"

#include "editor/editor_view.h"
#include "player/player_ui.h"
#include "player/view_navigation.h"

#include <atomic>
#include <catch2/catch.hpp>
#include <chrono>
#include <cmath>
#include <map>
#include <thread>

namespace playtest {

namespace fs = std::filesystem;
using namespace ib;
using Run = test::CommandRun;

const std::string kScene = std::string(INBETWEEN_ASSETS) + "/square-arch-notch/scene.json";

namespace {

// Where the readouts panel (play::readoutsPanel) and an error banner (play::messageBanner) sit
// over the picture: their samples are skipped.
bool underPanels(double x, double y) { return (x < 330 && y < 230) || y < 140; }

}  // namespace

Run inbetween(const std::string& args, const std::string& prefix) {
  return test::runCommand(prefix + " " + INBETWEEN_CLI + " " + args);
}

RgbaImage screenshot(const std::string& name, const std::string& options, int frames, const std::string& scene) {
  const std::string path = (fs::temp_directory_path() / ("inbetween-play-test-" + name + ".png")).string();
  fs::remove(path);
  const Run run = inbetween("play " + scene + " --frames " + std::to_string(frames) + " --screenshot " + path + " --size " +
                            std::to_string(kWidth) + "x" + std::to_string(kHeight) + " --device cpu --validation " + options);
  INFO(run.output);
  REQUIRE(run.code == 0);
  const RgbaImage image = readPng(path);
  REQUIRE(image.width == kWidth);
  REQUIRE(image.height == kHeight);
  return image;
}

RgbaImage drawing(const std::string& name) { return readPng(std::string(INBETWEEN_ASSETS) + "/square-arch-notch/" + name); }

int mismatches(const RgbaImage& shot, const RgbaImage& art, int tolerance, int* compared) {
  const play::PixelRect canvas = play::canvasRect(kWidth, kHeight);
  const render::ViewBox view = play::ViewNavigation().windowView({0, 0, double(art.width), double(art.height)}, canvas, kWidth, kHeight);
  const uint8_t backdrop = static_cast<uint8_t>(play::ViewSettings().backdrop.colour[0] * 255 + 0.5);
  int bad = 0;
  *compared = 0;
  for (int y = 3; y < art.height - 3; ++y)
    for (int x = 3; x < art.width - 3; ++x) {
      bool uniform = true;
      for (int dy = -3; dy <= 3 && uniform; ++dy)
        for (int dx = -3; dx <= 3 && uniform; ++dx)
          for (int c = 0; c < 4; ++c) uniform = uniform && art.at(x + dx, y + dy)[c] == art.at(x, y)[c];
      if (!uniform || (art.at(x, y)[3] != 0 && art.at(x, y)[3] != 255)) continue;
      const Eigen::Vector2d p = play::toWindow(view, kWidth, kHeight, {x + 0.5, y + 0.5});
      if (underPanels(p.x(), p.y())) continue;
      const uint8_t* got = shot.at(static_cast<int>(p.x()), static_cast<int>(p.y()));
      ++*compared;
      for (int c = 0; c < 3; ++c) {
        const int want = art.at(x, y)[3] == 255 ? art.at(x, y)[c] : backdrop;
        if (std::abs(int(got[c]) - want) > tolerance) {
          ++bad;
          break;
        }
      }
    }
  return bad;
}

int drawnMismatches(const RgbaImage& shot, const RgbaImage& art, bool nearest, int tolerance, int* compared) {
  const play::PixelRect canvas = play::canvasRect(kWidth, kHeight);
  const render::ViewBox view = play::ViewNavigation().windowView({0, 0, double(art.width), double(art.height)}, canvas, kWidth, kHeight);
  // Premultiplied texel (x, y) channel c; nothing beyond the drawing.
  const auto texel = [&](int x, int y, int c) {
    if (x < 0 || y < 0 || x >= art.width || y >= art.height) return 0.0;
    const uint8_t* p = art.at(x, y);
    return c == 3 ? double(p[3]) : p[c] * p[3] / 255.0;
  };
  // The drawing as the view samples it at each compared pixel (premultiplied RGBA), or nothing.
  struct Sample {
    int x, y;
    double want[4];
  };
  std::vector<Sample> samples;
  for (int py = 0; py < kHeight; ++py)
    for (int px = 0; px < kWidth; ++px) {
      if (underPanels(px + 0.5, py + 0.5) || !canvas.contains(px + 0.5, py + 0.5)) continue;
      const double u = view.x0 + (px + 0.5) / kWidth * (view.x1 - view.x0);
      const double v = view.y0 + (py + 0.5) / kHeight * (view.y1 - view.y0);
      if (u < 0 || v < 0 || u > art.width || v > art.height) continue;  // the canvas only
      Sample s{px, py, {}};
      if (nearest) {
        const double fu = u - std::floor(u), fv = v - std::floor(v);
        if (fu < 0.02 || fu > 0.98 || fv < 0.02 || fv > 0.98) continue;
        for (int c = 0; c < 4; ++c) s.want[c] = texel(int(std::floor(u)), int(std::floor(v)), c);
      } else {
        const double su = u - 0.5, sv = v - 0.5;
        const int x0 = int(std::floor(su)), y0 = int(std::floor(sv));
        const double fx = su - x0, fy = sv - y0;
        const auto clamped = [&](int x, int y, int c) {
          return texel(std::clamp(x, 0, art.width - 1), std::clamp(y, 0, art.height - 1), c);
        };
        for (int c = 0; c < 4; ++c)
          s.want[c] = (1 - fy) * ((1 - fx) * clamped(x0, y0, c) + fx * clamped(x0 + 1, y0, c)) +
                      fy * ((1 - fx) * clamped(x0, y0 + 1, c) + fx * clamped(x0 + 1, y0 + 1, c));
      }
      samples.push_back(s);
    }
  // The backdrop as presented: the commonest colour where the drawing has nothing.
  std::map<std::array<int, 3>, int> seen;
  for (const Sample& s : samples)
    if (s.want[3] == 0) {
      const uint8_t* p = shot.at(s.x, s.y);
      ++seen[{p[0], p[1], p[2]}];
    }
  std::array<int, 3> backdrop{};
  int most = 0;
  for (const auto& [colour, count] : seen)
    if (count > most) most = count, backdrop = colour;
  int bad = 0;
  *compared = static_cast<int>(samples.size());
  for (const Sample& s : samples) {
    const uint8_t* got = shot.at(s.x, s.y);
    for (int c = 0; c < 3; ++c)
      if (std::abs(got[c] - (s.want[c] + (1 - s.want[3] / 255) * backdrop[c])) > tolerance) {
        ++bad;
        break;
      }
  }
  return bad;
}

int pictureDifference(const RgbaImage& a, const RgbaImage& b) {
  const play::PixelRect canvas = play::canvasRect(kWidth, kHeight);
  int differ = 0;
  for (int y = 0; y < static_cast<int>(canvas.y1); ++y)
    for (int x = 0; x < static_cast<int>(canvas.x1); ++x) {
      if (underPanels(x, y)) continue;
      for (int c = 0; c < 3; ++c)
        if (std::abs(int(a.at(x, y)[c]) - int(b.at(x, y)[c])) > 32) {
          ++differ;
          break;
        }
    }
  return differ;
}


fs::path sceneCopy(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("inbetween-play-test-" + name);
  fs::remove_all(dir);
  fs::copy(fs::path(INBETWEEN_ASSETS) / "square-arch-notch", dir, fs::copy_options::recursive);
  return dir;
}

bool presentUntil(play::PlayerWindow& window, const std::function<bool()>& done, double seconds) {
  const auto start = std::chrono::steady_clock::now();
  while (std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() < seconds) {
    window.frame();
    if (done()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return false;
}

bool hasMessage(play::PlayerSession& session, bool error) {
  for (const play::PlayerSession::Message& m : session.messages())
    if (m.error == error) return true;
  return false;
}


std::string xdotool(const std::string& args) {
  std::string out = test::runCommand("xdotool " + args).output;
  while (!out.empty() && (out.back() == '\n' || out.back() == ' ')) out.pop_back();
  return out;
}

bool actUntil(const std::function<void()>& act, const std::function<bool()>& done, int attempts) {
  for (int a = 0; a < attempts; ++a) {
    act();
    for (int k = 0; k < 50; ++k) {
      if (done()) return true;
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
  }
  return false;
}

LiveWindow::LiveWindow(const std::string& scene, int width, int height, editor::EditorSession* editor)
    : session(std::make_unique<play::SceneReloader>(scene), {}) {
  play::PlayerWindowOptions options;
  options.editor = editor;
  options.width = width;
  options.height = height;
  options.validation = true;
  options.device = vk::DevicePreference::kSoftware;
  window = std::make_unique<play::PlayerWindow>(session, options);
  REQUIRE(presentUntil(*window, [&] { return session.shown() != nullptr; }, 60));
  REQUIRE(session.worker().waitIdle(60));
  id = xdotool("search --name \"inbetween (play|edit) - " + scene + "\" | head -n 1");
  REQUIRE_FALSE(id.empty());
  xdotool("windowfocus --sync " + id);
  frames(5);
}

LiveWindow::~LiveWindow() {
  const std::vector<std::string> messages = window->context().validationMessages();
  INFO((messages.empty() ? std::string() : messages.front()));
  CHECK(messages.empty());
}

void LiveWindow::frames(int count) {
  for (int i = 0; i < count; ++i) {
    window->frame();
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
}

RgbaImage LiveWindow::shot(const std::string& name) {
  RgbaImage image;
  REQUIRE(presentUntil(*window, [&] { return window->frame(&image); }, 10));
  writePng((fs::temp_directory_path() / ("inbetween-play-test-" + name + ".png")).string(), image);
  return image;
}

void LiveWindow::send(const std::string& args) { xdotool(withId(args)); }

void LiveWindow::sendWhilePresenting(const std::string& args) {
  std::atomic<bool> sent{false};
  std::thread input([&] {
    xdotool(withId(args));
    sent = true;
  });
  while (!sent) frames(1);
  input.join();
  frames(3);
}

std::string LiveWindow::withId(std::string args) const {
  for (size_t at = args.find("--window"); at != std::string::npos; at = args.find("--window", at + 1))
    args.insert(at + 8, " " + id);
  return args;
}

std::string at(ib::editor::EditorView& view, int key, double x, double y, int dx, int dy) {
  const Eigen::Vector2d p = view.toScreen(key, {x, y});
  return "mousemove --window " + std::to_string(static_cast<int>(std::lround(p.x())) + dx) + " " +
         std::to_string(static_cast<int>(std::lround(p.y())) + dy);
}

void clickControl(LiveWindow& live, ib::editor::EditorView& view, const std::string& name) {
  const std::optional<Eigen::Vector2d> c = view.buttonCentre(name);
  INFO(name);
  REQUIRE(c);
  live.send("mousemove --window " + std::to_string(static_cast<int>(c->x())) + " " + std::to_string(static_cast<int>(c->y())));
  live.frames(3);
  live.send("click 1");
  live.frames(3);
}

}  // namespace playtest
