#version 430 core
// Depth only; the depth attachment is all that is written.
void main() {}
