/* wrc profile reader plugin ABI (docs/design.md, section 6). Plain C; no C++ type crosses this boundary.
 *
 * A reader is a shared library exporting one function, WRC_READER_ENTRY_NAME ("wrc_reader_entry"), that
 * returns a versioned descriptor. The descriptor starts with the ABI version and its own size (as CLAP
 * does), so a host can refuse a plugin built against an incompatible ABI before touching anything else.
 * The host opens a file by calling `read` with a request (path, options) and a sink of host callbacks;
 * the reader hands over the points (with their source line numbers) and what it knows about them
 * (kind, length unit, the transformations it applied to reach the engine convention) and reports
 * failures as text with a line number. The host turns the result into a validated wrc::Profile and
 * applies the user's options (units, mirror_y, mirror_z, crop, shift).
 *
 * The engine convention the reader must deliver (docs/design.md, section 2): the LEFT-side profile frame,
 * y lateral and positive toward the field side, z UP. Wheels: y = s from the tape circle, z = radius
 * offset with the sign of height (flange tip of S1002 at z = -28 mm). Rails: origin as the file defines
 * it (the top of the head for uncanted rails). Lengths stay in the file's unit; `units` says which.
 *
 * Threading: the host may call `read` concurrently from several threads, each call with its own request
 * and sink; a reader keeps no mutable global state. Every function pointer below is non-null.
 *
 * ABI rules: a change that breaks old plugins or hosts bumps MAJOR; a field appended at the end of a
 * struct bumps MINOR (the struct_size fields let each side see which fields the other one has).
 */
#ifndef WRC_READER_H
#define WRC_READER_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define WRC_READER_ABI_MAJOR 1u
#define WRC_READER_ABI_MINOR 1u
#define WRC_READER_ENTRY_NAME "wrc_reader_entry"

#if defined(_WIN32)
#define WRC_READER_EXPORT __declspec(dllexport)
#else
#define WRC_READER_EXPORT __attribute__((visibility("default")))
#endif

/* Profile kinds, as in the request's kind hint and the sink's `kind` callback. */
#define WRC_KIND_UNKNOWN 0
#define WRC_KIND_WHEEL 1
#define WRC_KIND_RAIL 2

/* Axes of the sink's `reversed` callback. */
#define WRC_AXIS_Y 1
#define WRC_AXIS_Z 2

/* One reader-specific option, both strings owned by the host and valid during one `read` call. Numbers
 * are formatted with full precision ("0.001"), booleans as "true"/"false". */
typedef struct wrc_reader_option {
  const char* key;
  const char* value;
} wrc_reader_option;

/* What the host asks for. Owned by the host; valid only during the `read` call it is passed to. */
typedef struct wrc_reader_request {
  uint32_t struct_size;              /* sizeof(wrc_reader_request) as the host knows it */
  const char* path;                  /* file to read, as the user gave it (after path resolution) */
  int32_t kind_hint;                 /* WRC_KIND_*: the user's `kind` option, UNKNOWN when not given */
  const wrc_reader_option* options;  /* the options this reader declared, as given by the user */
  size_t option_count;
} wrc_reader_request;

/* Host callbacks. The sink and its `host` context are owned by the host and valid only during the `read`
 * call they are passed to; every string argument is copied by the host before the callback returns, so
 * the reader keeps ownership of its strings. */
typedef struct wrc_reader_sink {
  uint32_t struct_size; /* sizeof(wrc_reader_sink) as the host knows it */
  void* host;           /* opaque host context, passed back as the first argument of every callback */

  /* Appends one point (y, z) in the engine orientation and the file's length unit, read from source line
   * `line` (1-based; 0 when there is none). Returns 0, or non-zero when the host refuses the point (the
   * host has then recorded why): the reader stops and returns non-zero from `read`. */
  int (*point)(void* host, double y, double z, int32_t line);

  /* Declares the kind the file says it holds (WRC_KIND_WHEEL or WRC_KIND_RAIL). */
  void (*kind)(void* host, int32_t kind);

  /* Declares the length of one file unit in metres (0.001 for mm) and, in `declared_by`, where the file
   * says so ("units.len.f = 1000 (line 33)"). Without this call the host assumes millimetres. */
  void (*units)(void* host, double metres_per_unit, const char* declared_by);

  /* Describes one transformation the reader applied to reach the engine convention, in the order
   * applied ("Simpack mirror.y = 1 (line 30): y -> -y"). */
  void (*transform)(void* host, const char* description);

  /* Keeps one piece of information from the file (a header key, the file's comment). */
  void (*metadata)(void* host, const char* key, const char* value);

  /* Reports a failure at source line `line` (0 when no line applies) with a message that says what is
   * wrong and what was expected; the host prefixes the file name. `read` then returns non-zero. */
  void (*error)(void* host, int32_t line, const char* message);

  /* Since ABI 1.1 (call it only when struct_size covers it): says that a step the FILE asks for reversed the
   * lateral (WRC_AXIS_Y) or vertical (WRC_AXIS_Z) direction of its points, and how to undo it there, in `undo`
   * ("rotate = 180 (line 27) turns the points over: set rotate = 0 if they already have z down"). A reader's
   * own fixed conventions (a format's z down) are none. When the profile's shape then looks mirrored or
   * upside down (wrc/profile/orientation.hpp), the host names these steps instead of suggesting an option. */
  void (*reversed)(void* host, int32_t axis, const char* undo);
} wrc_reader_sink;

/* The plugin's description. Owned by the plugin: the descriptor, its strings and arrays are static and
 * stay valid until the library is unloaded (the host never unloads a plugin it accepted). */
typedef struct wrc_reader_descriptor {
  uint32_t abi_major;   /* WRC_READER_ABI_MAJOR the plugin was built against; must equal the host's */
  uint32_t abi_minor;   /* WRC_READER_ABI_MINOR the plugin was built against */
  uint32_t struct_size; /* sizeof(wrc_reader_descriptor) as the plugin knows it */
  const char* id;       /* unique reader id, [a-z0-9_]+ ("simpack"); `reader = "<id>"` picks it */
  const char* description;        /* one line for listings */
  const char* const* extensions;  /* NULL-terminated, lower case with the dot (".prr") */
  const char* const* options;     /* NULL-terminated keys of the reader's own options (may be empty) */

  /* Reads request->path into sink. Returns 0 on success; non-zero after at least one sink->error call.
   * Must not throw or longjmp across this boundary: the plugin catches everything. */
  int (*read)(const wrc_reader_request* request, const wrc_reader_sink* sink);
} wrc_reader_descriptor;

/* The one exported symbol. Returns the plugin's static descriptor (never freed by the host), or NULL if
 * the plugin cannot work in this process. */
typedef const wrc_reader_descriptor* (*wrc_reader_entry_fn)(void);

#ifdef __cplusplus
}
#endif

#endif /* WRC_READER_H */
