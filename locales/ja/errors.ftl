# `RecipeError` の各バリアントに 1 つずつのメッセージ（src/error.rs）。引数は
# `RecipeError::message_args` のもの。CSV の行番号は、テキストエディターや表計算ソフトと
# 同じく、ヘッダーを 1 行目として数える。

err-unknown-recipe = 「{ $id }」という名前のレシピはありません。「bsv --help」で一覧を表示できます。
err-unknown-flag = このレシピには「{ $flag }」というオプションはありません。
err-missing-flag-value = オプション「{ $flag }」の後ろに値を指定してください。
err-too-many-args = 値が多すぎます。このレシピが受け取る値は最大 { $max } 個ですが、{ $got } 個指定されています。
err-not-a-number = { $label }：「{ $value }」は数値ではありません。
err-not-an-integer = { $label }：「{ $value }」ではなく、3 や 800 のような整数を指定してください。
err-not-finite = { $label }：NaN や無限大ではなく、通常の数値を指定してください。
err-not-positive = { $label } は 0 より大きい値にしてください（現在の値: { $value }）。
err-out-of-range = { $label } は { $min } 以上 { $max } 以下にしてください（現在の値: { $value }）。
err-too-small = { $label } は { $min } 以上にしてください（現在の値: { $value }）。
err-too-big = { $label } は { $max } 以下にしてください（現在の値: { $value }）。
err-too-large = { $label }：この設定では { $count } 行（またはセル・反復）が必要になり、上限の { $limit } を超えます。刻みを大きくするか、範囲を狭くしてください。
err-wrong-count = { $label }：値が { $expected } 個必要ですが、{ $got } 個指定されています。
err-bad-choice = { $label }：「{ $value }」は選べません。次のいずれかを指定してください：{ $choices }
err-input-too-large = ファイルのサイズが { $bytes } バイトあり、上限の { $limit } バイトを超えています。
err-csv-missing-column = CSV には「{ $column }」という列が必要です。
err-csv-no-joint-columns = CSV に t_s 以外の関節の列がありません。q1 などの列を少なくとも 1 つ追加してください。
err-csv-too-few-rows = CSV のデータ行が { $rows } 行しかありません。少なくとも { $min } 行必要です。
err-csv-ragged = CSV の { $row } 行目はセルが { $got } 個ですが、ヘッダーは { $expected } 個です。
err-csv-bad-cell = CSV の { $row } 行目、列 { $column }：「{ $value }」は数値ではありません。
err-csv-time-not-increasing = CSV の { $row } 行目：t_s は前の行より大きくしてください（時刻は常に増えていく必要があります）。
err-csv-unterminated-quote = CSV の { $row } 行目：引用符（"）で始まった値が閉じられていません。
err-input-missing = 入力ファイル「{ $name }」が開かれていません。先にファイルを開いてから、もう一度実行してください。
err-input-not-utf8 = 「{ $name }」は UTF-8 のテキストではありません：オフセット { $offset }（先頭を 0 とする）のバイトが UTF-8 として正しくありません。UTF-8 で保存し直して（表計算ソフトなら「CSV UTF-8」）、もう一度開いてください。
err-input-utf16 = 「{ $name }」は UTF-16 のテキストです（UTF-16 のバイト順マークで始まっています）。このアプリが読むのは UTF-8 です。UTF-8 で保存し直して（表計算ソフトなら「CSV UTF-8」）、もう一度開いてください。
err-input-binary = 「{ $name }」に NUL バイトがあります（{ $line } 行目、その行の { $column } バイト目）。CSV のテキストではなくバイナリファイルです。
err-csv-too-many-columns = CSV のヘッダーに列が { $count } 個あります。読める列は { $limit } 個までです。
err-too-many-rows = { $label }：この組み合わせでは表が { $count } 行になり、上限の { $limit } 行を超えます。刻みを大きくするか、範囲を短くしてください。
err-grid-too-large = { $label }：この組み合わせでは格子が { $side } × { $side } セルになり、上限の { $limit } × { $limit } セルを超えます。刻みを大きくするか、半幅を小さくしてください。
err-point-in-obstacle = { $label }：点（{ $x }, { $y }）が障害物 { $index } の内側にあります（箱の辺の上も内側とみなします）。点を箱の外へ動かすか、箱を動かしてください。
err-box-inverted = { $label } { $index }（{ $box }）：角は x0,y0,x1,y1 の順で、x0 ≤ x1 かつ y0 ≤ y1 にしてください。
err-too-many-values = { $label }：{ $count } 回指定されていますが、指定できるのは { $limit } 回までです。

# 警告（`RecipeWarning`、src/error.rs）：実行は終わり CSV も書かれたが、結果はおそらく意図した
# ものではない。結果の横に表示する。
warn-diverged = ループが不安定です。出力が際限なく大きくなっています（最大の大きさ { $peak }、最終値 { $final }）。ゲインを小さくしてみてください。
warn-not-finite = ループが発散しました。出力が無限大にあふれ、ステップ { $step } 以降は「nan」になっています。ゲインを小さくしてみてください。
warn-goal-not-reached = 反復 { $iterations } 回以内に木がゴールへ届きませんでした。経路ファイルは空です。反復回数を増やすか、ゴールを動かしてください。
warn-goal-in-obstacle = ゴール（{ $x }, { $y }）が障害物の内側にあるため、どの経路も届きません。
warn-energy-grows = 減衰はエネルギーを増やさないのに、全エネルギーが { $percent } % 増えました。この積分法には時間刻みが大きすぎます。刻みを小さくするか、rk4 を使ってください。
warn-few-points = 点の組が { $n } 組しかありません。どんなノイズでも当てはめは完全に一致するため、誤差からは何もわかりません。3 組以上にしてください。
