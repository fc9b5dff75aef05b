namespace fixture {
int none() { return 0; }
}  // namespace fixture
