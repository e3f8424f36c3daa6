// The shadow pass writes depth only.
void main() {}
