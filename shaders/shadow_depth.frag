// Depth only: the fixed-function depth (with the pass's slope-scaled offset) is all that is stored.
void main() {
}
