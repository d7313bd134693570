// The tone-mapping display pass (render/display.h).
#include "render/display.h"

#include "render/texture_units.h"
#include "shadergen/shadergen.h"

namespace pt {

Display::Display(ToneMap first) { programs_[int(first)] = Program(fullscreen_vertex(), generate_display(first)); }

void Display::draw(const Texture& mean, ToneMap tonemap, float exposure, int x, int y, GLuint vao, int scale, int w, int h) const {
  Program& p = programs_[int(tonemap)];
  if (!p.id()) p = Program(fullscreen_vertex(), generate_display(tonemap));
  p.use();
  p.set("u_accum", int(kAccumUnit));
  p.set("u_exposure", exposure);
  p.set("u_offset", glm::ivec2(x, y));
  p.set("u_scale", scale);
  mean.bind(kAccumUnit);
  glViewport(x, y, w > 0 ? w : mean.width(), h > 0 ? h : mean.height());
  glDisable(GL_BLEND);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_SCISSOR_TEST);
  glBindVertexArray(vao);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  PT_GL_CHECK("glDrawArrays (display)");
}

std::vector<uint8_t> Display::read(const Texture& mean, ToneMap tonemap, float exposure, GLuint vao, int scale, int w, int h) const {
  if (w <= 0 || h <= 0) w = mean.width(), h = mean.height();
  Texture t(w, h, GL_RGBA8, nullptr);
  Framebuffer f(t);
  glBindFramebuffer(GL_FRAMEBUFFER, f.id());
  draw(mean, tonemap, exposure, 0, 0, vao, scale, w, h);
  std::vector<uint8_t> out(size_t(w) * h * 4);
  glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, out.data());
  PT_GL_CHECK("glReadPixels (display)");
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  return out;
}

}  // namespace pt
