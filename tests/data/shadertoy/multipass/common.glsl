// Common: shared by every pass of counter.json.
float count_scale() { return 10.0; }
