// The ABI entry point of one reader plugin, compiled into each plugin with WRC_READER_SPEC naming that
// plugin's ReaderSpec (see wrc_add_reader_plugin in plugins/CMakeLists.txt).
#include "reader_support.hpp"

#ifndef WRC_READER_SPEC
#error "WRC_READER_SPEC must name the plugin's wrc::plugin::ReaderSpec"
#endif

namespace wrc::plugin {
extern const ReaderSpec WRC_READER_SPEC;
}

namespace {

int read_entry(const wrc_reader_request* request, const wrc_reader_sink* sink) {
  return wrc::plugin::run_reader(wrc::plugin::WRC_READER_SPEC, request, sink);
}

const wrc_reader_descriptor* descriptor() {
  static const wrc_reader_descriptor d = {
      WRC_READER_ABI_MAJOR,
      WRC_READER_ABI_MINOR,
      static_cast<uint32_t>(sizeof(wrc_reader_descriptor)),
      wrc::plugin::WRC_READER_SPEC.id,
      wrc::plugin::WRC_READER_SPEC.description,
      wrc::plugin::WRC_READER_SPEC.extensions,
      wrc::plugin::WRC_READER_SPEC.options,
      read_entry,
  };
  return &d;
}

}  // namespace

extern "C" WRC_READER_EXPORT const wrc_reader_descriptor* wrc_reader_entry(void) { return descriptor(); }
