#pragma once
// The studio's requests as plain functions: request body in, reply out, no
// HTTP. Everything the page sends is read as a scene file is
// (scene_from_text, apply_json, validate), so a bad value gets the same
// message, naming the same key, as on the command line.
#include <cstddef>
#include <map>
#include <optional>
#include <string>

#include "src/scene_file.h"

namespace sandpic::studio {

// A request body past this is refused before it is parsed: a scene is a few
// kB, a sketch with long strokes some hundred kB.
constexpr size_t kMaxRequestBytes = 1 << 20;
// A picture dropped on the page for halftoning (paper §4.2): a photo's size.
constexpr size_t kMaxImageBytes = 16 << 20;
constexpr double kMaxImagePixels = 50e6;

// A request body over its limit: 413, not 400.
struct TooLarge : InputError {
  using InputError::InputError;
};

struct Reply {
  int status = 200;
  std::string content_type = "application/json";
  std::string body;
  std::map<std::string, std::string> headers;
};

// 400 with {"error": message, "key": "physics.friction"} ("key" empty when
// the message names none), so the page can show it beside the control.
Reply error_reply(const std::string& message, int status = 400);
Reply json_reply(const ordered_json& doc);
// "physics.friction" from "... scene key 'physics.friction': ...", or "".
std::string key_of(const std::string& message);

// The scene a request body describes, checked as a scene file is; image and
// calibration paths resolve from `root` and must stay inside it. Throws
// InputError naming the key.
Scene scene_from_request(const std::string& body, const std::string& root);
// The whole of `text` as a number, or nullopt (query parameters).
std::optional<double> number_of(const std::string& text);
// The `scale` query parameter ("" = 1): a number in (0, 4], else InputError
// naming it. The page renders the final DEM smaller than the design.
double scale_param(const std::string& text);
// `s` with every length in px times `scale`, checked again.
Scene scaled(Scene s, double scale);
// Throws InputError naming `key` if `path`, from `root`, leads outside it.
void check_inside(const std::string& root, const std::string& path, const std::string& key);

// DNS rebinding and cross-site requests: a studio listening on loopback
// answers only requests addressed to a loopback name (the Host header), and
// takes a POST only from its own page (the Origin header, when the browser
// sends one), so a web page on another site the designer has open cannot
// read the studio or start renders. A studio told to listen elsewhere
// (--host) checks neither. "" when the request may go on, else why not.
bool is_loopback(const std::string& host);
std::string refusal(const std::string& listen_host, const std::string& method, const std::string& host_header,
                    const std::string& origin);

// POST /api/image: a picture for halftoning, its bytes as the body. It is
// decoded (InputError if it is no picture OpenCV reads, or over
// kMaxImagePixels), kept as PNG under root/studio-inputs/ named by its
// content (the same picture twice is one file), and answered with
// {"path": "studio-inputs/image-HASH.png", "width", "height"}: the path a
// scene's init.image takes.
Reply upload_image(const std::string& bytes, const std::string& root);

// The scene the page starts from, as JSON (every key).
Reply scene_reply(const Scene& s);
// POST /api/scene: the complete scene (every key) a body describes: a
// dropped scene file or a preset, read back into the page's controls.
Reply complete_scene(const std::string& body, const std::string& root);
// POST /api/preview: the scene's lattice picture as PNG, its stats (JSON) in
// the X-Sandpic-Stats header. Same body, same bytes.
// `scale` as --scale (apply_scale).
Reply preview(const std::string& body, const std::string& root, double scale = 1);
// POST /api/units: the falling units the scene's segmentation yields, to
// draw over the sketch: {"ellipses": [[cx, cy, a, b, theta], ...],
// "cells": [[x0, y0, x1, y1], ...], "tessellation": [[x0, y0, x1, y1,
// dominant, secondary], ...]} in window px; the tessellation's cells are
// numbered as init.cell_overrides numbers them (empty for halftone).
Reply units(const std::string& body, const std::string& root);

}  // namespace sandpic::studio
