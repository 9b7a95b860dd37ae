/* A reader plugin built out of tree, against an installed wrc alone (tests/out_of_tree/plugin_check.cmake):
 * survey stations, one point per line, "<label> <y> <z>" in millimetres in the engine frame, after a first line
 * "stations wheel" or "stations rail"; '#' starts a comment. Its own option `first` (a label) skips the stations
 * before that one. */
#include <wrc/reader.h>

#include <stdio.h>
#include <string.h>

static const char* const extensions[] = {".sta", NULL};
static const char* const options[] = {"first", NULL};

static const char* option(const wrc_reader_request* request, const char* key) {
  for (size_t i = 0; i < request->option_count; ++i)
    if (strcmp(request->options[i].key, key) == 0) return request->options[i].value;
  return NULL;
}

static int fail(const wrc_reader_sink* sink, FILE* f, int line, const char* message) {
  sink->error(sink->host, line, message);
  if (f) fclose(f);
  return 1;
}

static int read_stations(const wrc_reader_request* request, const wrc_reader_sink* sink) {
  FILE* f = fopen(request->path, "r");
  char text[512], label[64], kind[16], extra;
  const char* first = option(request, "first");
  int line = 0, started = first == NULL;
  double y, z;
  if (!f) return fail(sink, NULL, 0, "cannot open the file");
  if (!fgets(text, sizeof text, f) || sscanf(text, "stations %15s %c", kind, &extra) != 1 ||
      (strcmp(kind, "wheel") != 0 && strcmp(kind, "rail") != 0))
    return fail(sink, f, 1, "expected a first line `stations wheel` or `stations rail`");
  ++line;
  sink->kind(sink->host, strcmp(kind, "wheel") == 0 ? WRC_KIND_WHEEL : WRC_KIND_RAIL);
  sink->units(sink->host, 0.001, "stations are in mm");
  while (fgets(text, sizeof text, f)) {
    ++line;
    char* hash = strchr(text, '#');
    if (hash) *hash = '\0';
    if (sscanf(text, " %c", &extra) != 1) continue; /* blank */
    if (sscanf(text, "%63s %lf %lf %c", label, &y, &z, &extra) != 3)
      return fail(sink, f, line, "expected `<label> <y> <z>` (mm)");
    if (!started) started = strcmp(label, first) == 0;
    if (started && sink->point(sink->host, y, z, line) != 0) {
      fclose(f);
      return 1;
    }
  }
  fclose(f);
  if (first && !started) return fail(sink, NULL, 0, "no station with the label given by `first`");
  if (first) sink->transform(sink->host, "stations: the ones before `first` skipped");
  return 0;
}

static const wrc_reader_descriptor descriptor = {
    WRC_READER_ABI_MAJOR, WRC_READER_ABI_MINOR, (uint32_t)sizeof(wrc_reader_descriptor), "station",
    "survey stations (label y z, mm)", extensions, options, read_stations,
};

WRC_READER_EXPORT const wrc_reader_descriptor* wrc_reader_entry(void) { return &descriptor; }
