# One message per `RecipeError` variant (src/error.rs); the arguments are those of
# `RecipeError::message_args`. CSV line numbers count the header as line 1, as a text
# editor or spreadsheet shows them.

err-unknown-recipe = There is no recipe called “{ $id }”. Run “bsv --help” to list them.
err-unknown-flag = This recipe has no option “{ $flag }”.
err-missing-flag-value = The option “{ $flag }” needs a value after it.
err-too-many-args = Too many values: this recipe takes at most { $max }, but got { $got }.
err-not-a-number = { $label }: “{ $value }” is not a number.
err-not-an-integer = { $label }: “{ $value }” must be a whole number, such as 3 or 800.
err-not-finite = { $label }: must be an ordinary number, not NaN or infinity.
err-not-positive = { $label } must be greater than zero (it is { $value }).
err-out-of-range = { $label } must be between { $min } and { $max } (it is { $value }).
err-too-small = { $label } must be at least { $min } (it is { $value }).
err-too-big = { $label } must be at most { $max } (it is { $value }).
err-too-large = { $label }: this would need { $count } rows, cells or steps; the limit is { $limit }. Use a larger step or a smaller range.
err-wrong-count = { $label }: needs { $expected } values, got { $got }.
err-bad-choice = { $label }: “{ $value }” is not one of the choices ({ $choices }).
err-input-too-large = The file is { $bytes } bytes; the limit is { $limit } bytes.
err-csv-missing-column = The CSV needs a column named “{ $column }”.
err-csv-no-joint-columns = The CSV has no joint columns besides t_s. Add at least one, such as q1.
err-csv-too-few-rows = The CSV has { $rows ->
    [one] { $rows } data row
   *[other] { $rows } data rows
}; at least { $min } are needed.
err-csv-ragged = CSV line { $row } has { $got } cells, but the header has { $expected }.
err-csv-bad-cell = CSV line { $row }, column { $column }: “{ $value }” is not a number.
err-csv-time-not-increasing = CSV line { $row }: t_s must be larger than on the line before (time must always increase).
err-csv-unterminated-quote = CSV line { $row }: a value opened with a quote (") is never closed.
err-input-missing = The input file “{ $name }” is not open. Open the file first, then run again.
err-input-not-utf8 = “{ $name }” is not UTF-8 text: the byte at offset { $offset } (counted from 0) is not valid UTF-8. Save the file as UTF-8 (in a spreadsheet: “CSV UTF-8”) and open it again.
err-input-utf16 = “{ $name }” is UTF-16 text (it starts with a UTF-16 byte-order mark); this app reads UTF-8. Save the file as UTF-8 (in a spreadsheet: “CSV UTF-8”) and open it again.
err-input-binary = “{ $name }” holds a NUL byte (line { $line }, byte { $column } of the line): it is a binary file, not CSV text.
err-csv-too-many-columns = The CSV header has { $count } columns; at most { $limit } are read.
err-too-many-rows = { $label }: with these values the table would have { $count } rows; the limit is { $limit }. Use a larger step or a shorter span.
err-grid-too-large = { $label }: with these values the grid would be { $side } × { $side } cells; the limit is { $limit } × { $limit }. Use a larger step or a smaller half-extent.
err-point-in-obstacle = { $label }: the point ({ $x }, { $y }) lies inside obstacle { $index } (its edges count as inside). Move it out of the box, or move the box.
err-box-inverted = { $label } { $index } ({ $box }): the corners are x0,y0,x1,y1 with x0 ≤ x1 and y0 ≤ y1.
err-too-many-values = { $label }: given { $count } times; at most { $limit } are allowed.

# Warnings (`RecipeWarning`, src/error.rs): the run finished and wrote its CSV, but the result
# is probably not what was meant. Shown beside the result.
warn-diverged = The loop is unstable: the output grows without bound (largest size { $peak }, final value { $final }). Try smaller gains.
warn-not-finite = The loop blew up: the output overflowed to infinity and then became “nan” from step { $step } on. Try smaller gains.
warn-goal-not-reached = The tree did not reach the goal within { $iterations } iterations; the path file is empty. Raise the iteration budget or move the goal.
warn-goal-in-obstacle = The goal ({ $x }, { $y }) is inside the obstacle, so no path can ever reach it.
warn-energy-grows = The total energy grew by { $percent } % although damping never adds energy: the time step is too large for this integrator. Try a smaller step or rk4.
warn-few-points = Only { $n } point pairs: the fit is exact for any noise, so the error says nothing. Use at least 3.
