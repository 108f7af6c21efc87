// Placeholder translation unit so tephra_models is a real library until the
// first model lands (issue 4).
namespace tephra::models {
int registry_version() { return 1; }
}  // namespace tephra::models
