# One message per `RecipeError` variant (src/error.rs); the arguments are those of
# `RecipeError::message_args`. CSV line numbers count the header as line 1, as a text
# editor or spreadsheet shows them.

err-unknown-recipe = There is no recipe called “{ $id }”. Run “bsv --help” to list them.
err-unknown-flag = This recipe has no option “{ $flag }”.
err-missing-flag-value = The option “{ $flag }” needs a value after it.
err-too-many-args = Too many values: this recipe takes at most { $max }, but got { $got }.
err-not-a-number = { $param }: “{ $value }” is not a number.
err-not-an-integer = { $param }: “{ $value }” must be a whole number, such as 3 or 800.
err-not-finite = { $param }: must be an ordinary number, not NaN or infinity.
err-not-positive = { $param } must be greater than zero (it is { $value }).
err-out-of-range = { $param } must be between { $min } and { $max } (it is { $value }).
err-too-large = { $param }: this would need { $count } rows, cells or steps; the limit is { $limit }. Use a larger step or a smaller range.
err-wrong-count = { $param }: needs { $expected } values, got { $got }.
err-bad-choice = { $param }: “{ $value }” is not one of the choices ({ $choices }).
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
