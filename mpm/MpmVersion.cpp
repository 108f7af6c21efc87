namespace tephra::mpm {
int mpm_version() { return 0; }
}  // namespace tephra::mpm
