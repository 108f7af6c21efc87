// ICE arrives with issue 5; this unit keeps the library target real.
namespace tephra::ice {
int ice_version() { return 0; }
}  // namespace tephra::ice
