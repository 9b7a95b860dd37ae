/* A reader plugin written in plain C, built in several variants to test the host's plugin loading:
 *   WRC_TEST_GOOD          id "ctest", reads ".ctest" files of `y z` lines (mm), kind from the request
 *   WRC_TEST_NO_ENTRY      exports no entry point
 *   WRC_TEST_BAD_MAJOR     declares ABI major 99
 *   WRC_TEST_DUPLICATE_ID  declares the id "text", which the project's text reader has
 *   WRC_TEST_NULL          the entry point returns NULL
 *   WRC_TEST_SMALL_STRUCT  declares a descriptor smaller than the host's
 */
#include "wrc/reader.h"

#include <stdio.h>
#include <string.h>

static const char* const extensions[] = {".ctest", NULL};
static const char* const options[] = {NULL};

/* Reads `y z` pairs; reports the first malformed line. */
static int read_pairs(const wrc_reader_request* request, const wrc_reader_sink* sink) {
  FILE* f = fopen(request->path, "r");
  char line[512];
  int number = 0;
  if (!f) {
    sink->error(sink->host, 0, "cannot open the file");
    return 1;
  }
  sink->kind(sink->host, request->kind_hint == WRC_KIND_UNKNOWN ? WRC_KIND_RAIL : request->kind_hint);
  sink->units(sink->host, 0.001, "the ctest format is always mm");
  sink->transform(sink->host, "ctest: read as given");
  while (fgets(line, sizeof line, f)) {
    double y, z;
    char extra;
    ++number;
    if (sscanf(line, "%lf %lf %c", &y, &z, &extra) != 2) {
      sink->error(sink->host, number, "expected two numbers `y z`");
      fclose(f);
      return 1;
    }
    if (sink->point(sink->host, y, z, number) != 0) {
      fclose(f);
      return 1;
    }
  }
  fclose(f);
  return 0;
}

#if defined(WRC_TEST_DUPLICATE_ID)
#define TEST_ID "text"
#else
#define TEST_ID "ctest"
#endif

#if defined(WRC_TEST_BAD_MAJOR)
#define TEST_MAJOR 99u
#else
#define TEST_MAJOR WRC_READER_ABI_MAJOR
#endif

#if defined(WRC_TEST_SMALL_STRUCT)
#define TEST_SIZE 8u
#else
#define TEST_SIZE ((uint32_t)sizeof(wrc_reader_descriptor))
#endif

__attribute__((unused)) static const wrc_reader_descriptor descriptor = {
    TEST_MAJOR, WRC_READER_ABI_MINOR, TEST_SIZE, TEST_ID, "C test reader", extensions, options, read_pairs,
};

#if defined(WRC_TEST_NO_ENTRY)
WRC_READER_EXPORT const wrc_reader_descriptor* some_other_symbol(void) { return &descriptor; }
#elif defined(WRC_TEST_NULL)
WRC_READER_EXPORT const wrc_reader_descriptor* wrc_reader_entry(void) { return NULL; }
#else
WRC_READER_EXPORT const wrc_reader_descriptor* wrc_reader_entry(void) { return &descriptor; }
#endif
