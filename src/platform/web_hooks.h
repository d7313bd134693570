// The page's side of the web platform (web_hooks.cpp): the functions the page's
// JavaScript (web/index.html, web/files.js) and the browser tests call, and what the app
// asks of the page. web.cpp, the platform glue, creates the app and runs the frames.
#pragma once
#include "app/app.h"

namespace pt::web {

// The options the app starts with: the page's URL parameters, which web/index.html
// passes as the program's arguments, and the page's file download and scene fetch.
AppOptions page_options(int argc, char** argv);

// The app the exported functions act on; until it is set they answer as without a scene.
void set_app(App* app);

// A message in place of the canvas (web/index.html's ptShowError).
void show_error(const char* message);

// Whether the canvas has keyboard focus (keys drive the camera only then).
bool canvas_focused();

// Slices of the scene preparation in progress between animation frames (pt_work), until
// none remains.
void pump_work(double slice_ms);

}  // namespace pt::web
