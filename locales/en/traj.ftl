# The trajectory-resampling page (#/traj-resample). Ids start with `traj-`.
traj-lede = A joint trajectory sampled at irregular times, linearly interpolated onto a uniform time grid t0, t0 + dt, … as the recipe does it. Open your CSV with the button or drop it anywhere on this page; it never leaves your computer.

traj-plot-title = Joints over time
traj-canvas-label = Plot of each joint against time: the file's samples as dots, the resampled series as a line.
traj-plot-note = Dots: the samples of the file. Line: the resampled series at dt. Long files are drawn from their lowest and highest value per pixel column, so no spike is lost.
traj-series-samples = samples
traj-series-resampled = resampled
traj-axis-time = time t_s

traj-readouts-title = The trajectory
traj-ro-rows-in = Rows in the file
traj-ro-joints = Joint columns
traj-ro-span = Time span
traj-ro-duration = Duration
traj-ro-dt = Time step dt
traj-ro-rows-out = Rows resampled
traj-span-value = { $first } s to { $last } s
traj-seconds = { $s } s
traj-live = { $rows_in } rows, { $joints } joints over { $duration } s, resampled to { $rows_out } rows.
traj-drop-note = Drop a CSV file anywhere on this page to open it.

traj-input-title = Input and time step
traj-input-sample = Using the recipe's labeled sample ({ $name }).
traj-input-file = Using your file “{ $name }”.
traj-input-missing = The link used the file “{ $name }”: open it again.
traj-file-unreadable = “{ $name }” could not be read ({ $reason }).
traj-file-too-large = “{ $name }” is { $size } MiB: over the { $limit } MiB a trajectory may have here (bsv has the same limit). Split the file or resample a part of it.
traj-reading = Reading the file…
traj-running = Resampling in the background; the page stays usable.
traj-failed = The recipe refused this input; the message beside the field says why. The last result stays.
traj-done = Resampled in { $ms } ms.
traj-done-worker = Resampled in the background in { $ms } ms.

traj-exports-title = Download
traj-download-png = Plot as PNG

traj-key-open = Open a CSV file
traj-key-sample = Use the labeled sample
traj-key-download = Download traj_resampled.csv

traj-explain-title = What the recipe does
traj-explain-input-label = Input
traj-explain-input = Optional CSV path (t_s,q1,q2,...) and dt seconds (default 0.02).
traj-explain-output-label = Output
traj-explain-output = traj_resampled.csv on the uniform grid.
traj-explain-steps-label = Steps
traj-explain-steps = Run python joint_traj_resample.py, or python joint_traj_resample.py your.csv 0.02, then confirm the row count ≈ duration / dt.
traj-explain-expected-label = Expected result
traj-explain-expected = More rows than the irregular sample. Synthetic notes stay example-row until you swap files.
traj-explain-interp-title = Linear interpolation
traj-explain-interp = For each new time x, the recipe finds the last sample at or before it and draws a straight line to the next one (numpy's interp); the grid starts at the first time and stops at the last (plus 1e-12 so the last time can land on it). The output's t_s has 6 decimals and the joints 8, as the recipe writes them.
traj-explain-quirks-title = Quirks
traj-explain-decoding-title = Files that are not UTF-8
traj-explain-decoding = The page and bsv read a file the same way: as UTF-8 (a byte-order mark is fine). Any other encoding is refused with the offset of the first byte that is not UTF-8, never guessed, so both always read the same numbers.
