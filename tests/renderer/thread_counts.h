#pragma once
// The determinism tests' pair: one view rendered on one thread and on two (the same bits are
// expected on any thread count).
#include "renderer/transport/render.h"

namespace landsim::test {

struct OneAndTwoThreads {
  renderer::Film one, two;
};

inline OneAndTwoThreads render_on_one_and_two_threads(const renderer::Renderer& renderer,
                                                      const renderer::View& view) {
  renderer::RenderOptions one, two;
  one.threads = 1;
  two.threads = 2;
  return {renderer.render(view, one), renderer.render(view, two)};
}

}  // namespace landsim::test
