/* app_version.c: version string of the application layer */
const char* ura_version(void) { return "0.1.0"; }
