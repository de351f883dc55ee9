#pragma once
// lidr's public API in one include: #include <lidr/lidr.h>, link lidr::lidr (find_package(lidr)).
//
// It names no GL header: GL types come from lidr/base/gl_types.h, so GLFW, SDL, <GL/gl.h>, GLEW or any other
// loader may be included before or after it. lidr loads its own GL entry points (GLEW) inside the library.
//
//   contexts     lidr::GlContext::create()  (headless EGL, GLFW window; lidr/platform/context.h), or your own:
//                lidr::currentContextGlInfo() reads the context current on this thread (lidr/gl/gl_info.h)
//   scenes       lidr::Scene, lidr::makeDefaultScene(), lidr::loadSceneFile(), primitives, lidr::Camera
//   renderers    lidr::LidrRenderer (LidrOptions), or lidr::createRenderer() for any mode by name: "lidr",
//                "tiled" (TiledOptions), "clustered" (ClusteredOptions), "forward-multipass", "forward-brute", "auto"
//   output       Renderer::targets().readColor() -> ImageRGBA8 -> lidr::writePng(), or
//                lidr::FramePresenter::present() into your framebuffer or FBO (lidr/render/present.h)
//   environment  lidr::defaultEnvironment() (a studio room) or lidr::loadEnvironment("sky.hdr"): set
//                ShadingParameters::environment (or Scene::environment, which sceneShading copies) for image-based
//                light (doc/colour.md, "Environment light"; lidr/scene/environment.h)
//   your shaders LidrOptions::materialShader: a GLSL 1.20 fragment shader that includes "lidr_lights.glsl"
//                (doc/embedding.md)
// Every renderer leaves the GL state it found (doc/embedding.md lists what is kept); lidr::SavedGlState keeps
// it around anything else of lidr's (constructors, read-backs).
#include "lidr/base/error.h"
#include "lidr/base/image.h"
#include "lidr/gl/gl_info.h"
#include "lidr/gl/saved_gl_state.h"
#include "lidr/platform/context.h"
#include "lidr/scene/camera.h"
#include "lidr/scene/default_scene.h"
#include "lidr/scene/primitives.h"
#include "lidr/scene/scene.h"
#include "lidr/scene/environment.h"
#include "lidr/scene/io/environment_file.h"
#include "lidr/scene/io/scene_loader.h"
#include "lidr/render/present.h"
#include "lidr/render/renderer.h"
#include "lidr/render/shadow_casters.h"
#include "lidr/technique/lidr_renderer.h"
#include "lidr/modes/render_mode.h"
#include "lidr/modes/render_options.h"
#include "lidr/modes/tiled_renderer.h"
#include "lidr/modes/clustered_renderer.h"
#include "lidr/modes/auto_mode_renderer.h"
#include "lidr/eval/image_compare.h"
