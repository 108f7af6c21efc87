namespace tephra::mpmice {
int mpmice_version() { return 0; }
}  // namespace tephra::mpmice
