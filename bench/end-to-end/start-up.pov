// Nothing to render: POV-Ray's time on this one pixel is its start-up (the
// program, its configuration, its threads), which the end-to-end benchmark
// takes off its time on the real scene.
camera { location <0, 0, -1> look_at <0, 0, 0> }
