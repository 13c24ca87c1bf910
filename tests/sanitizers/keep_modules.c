/* keep_modules.c - preloaded (LD_PRELOAD) into the ASan+UBSan CTest run by
 * scripts/run-sanitizers.sh: dlclose() keeps every shared object mapped
 * until the process exits.
 *
 * Why: LeakSanitizer treats memory as reachable while a pointer to it sits in
 * a loaded module's globals. Mesa unloads its driver in eglTerminate(), so the
 * driver's process-lifetime caches lose their roots and are reported as leaks
 * from "<unknown module>", a frame no suppression can name (seen in
 * example_minimal_host, which terminates its display as the README shows).
 * Kept mapped, that memory is reachable again, and any real leak, ours
 * included, is still reported, now with its module's name and symbols, also
 * for a plugin a test dlclose()s. Nothing is suppressed by this file. */
int dlclose(void* handle) {
    (void)handle;
    return 0;
}
