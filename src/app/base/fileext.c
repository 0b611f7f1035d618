/* fileext.c: what a file name's extension says it holds. A writer that writes one format (report:
 * HTML, export: CSV, save session and model save: text of their own) refuses a name whose
 * extension names another (report x.txt), so that nobody opens an HTML page as text; a name
 * without an extension, or with one no format here has, is taken as it is. */
#include <string.h>
#include <strings.h>

#include "base.h"

/* extensions and the format each names (the plot terminals' names for images: plot_file.c) */
static const char* const ext_format[][2] = {
    {"html", "HTML"},   {"htm", "HTML"},  {"xhtml", "HTML"},       {"csv", "CSV"},
    {"tsv", "TSV"},     {"txt", "text"},  {"text", "text"},        {"json", "JSON"},
    {"ses", "session"}, {"urm", "model"}, {"png", "PNG"},          {"svg", "SVG"},
    {"pdf", "PDF"},     {"eps", "EPS"},   {"ps", "PostScript"},    {"jpg", "JPEG"},
    {"jpeg", "JPEG"},   {"gif", "GIF"},   {"md", "Markdown"},      {"xml", "XML"},
    {"xlsx", "Excel"},  {"xls", "Excel"}, {"ods", "OpenDocument"}, {"odt", "OpenDocument"},
    {"doc", "Word"},    {"docx", "Word"}, {"tex", "TeX"},          {NULL, NULL}};

const char* ura_ext_format(const char* path) {
  const char* base = strrchr(path, '/');
  base = base ? base + 1 : path;
  const char* dot = strrchr(base, '.');
  if (!dot || dot == base) return NULL; /* no extension, or a hidden file's name */
  for (int i = 0; ext_format[i][0]; i++) {
    if (!strcasecmp(dot + 1, ext_format[i][0])) return ext_format[i][1];
  }
  return NULL;
}

const char* ura_format_ext(const char* format) {
  for (int i = 0; ext_format[i][0]; i++) {
    if (!strcmp(ext_format[i][1], format)) return ext_format[i][0];
  }
  return NULL;
}

int ura_ext_fits(const char* path, const char* exts) {
  const char* f = ura_ext_format(path);
  if (!f) return 1;
  const char* dot = strrchr(path, '.');
  for (const char* e = exts; *e;) {
    size_t n = strcspn(e, " ");
    if (n == strlen(dot + 1) && !strncasecmp(dot + 1, e, n)) return 1;
    e += n + strspn(e + n, " ");
  }
  return 0;
}
