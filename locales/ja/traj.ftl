# 軌道のリサンプリングのページ（#/traj-resample）。ID は `traj-` で始まる。
traj-lede = 不規則な時刻でサンプルされた関節軌道を、レシピと同じ方法で等間隔の時刻 t0、t0 + dt、… に線形補間します。CSV はボタンで開くか、このページのどこかにドロップしてください。ファイルがこのコンピューターの外に出ることはありません。

traj-plot-title = 関節の時間変化
traj-canvas-label = 各関節の時間に対するグラフ：点はファイルのサンプル、線はリサンプリングした系列。
traj-plot-note = 点：ファイルのサンプル。線：dt でリサンプリングした系列。長いファイルは画素の列ごとの最小値と最大値で描くので、スパイクも消えません。
traj-series-samples = サンプル
traj-series-resampled = リサンプリング後
traj-axis-time = 時刻 t_s

traj-readouts-title = 軌道
traj-ro-rows-in = ファイルの行数
traj-ro-joints = 関節の列数
traj-ro-span = 時間の範囲
traj-ro-duration = 長さ
traj-ro-dt = 時間刻み dt
traj-ro-rows-out = リサンプリング後の行数
traj-span-value = { $first } 秒 〜 { $last } 秒
traj-seconds = { $s } 秒
traj-live = { $rows_in } 行、{ $joints } 関節、{ $duration } 秒の軌道を { $rows_out } 行にリサンプリングしました。
traj-drop-note = CSV ファイルをこのページのどこかにドロップすると開きます。

traj-input-title = 入力と時間刻み
traj-input-sample = レシピのラベル付きサンプル（{ $name }）を使っています。
traj-input-file = ファイル「{ $name }」を使っています。
traj-input-missing = このリンクではファイル「{ $name }」が使われていました。もう一度開いてください。
traj-file-unreadable = 「{ $name }」を読み込めませんでした（{ $reason }）。
traj-file-too-large = 「{ $name }」は { $size } MiB で、ここで扱える軌道の上限 { $limit } MiB（bsv と同じ）を超えています。ファイルを分けるか、一部だけをリサンプリングしてください。
traj-reading = ファイルを読み込んでいます…
traj-running = バックグラウンドでリサンプリングしています。その間もページは使えます。
traj-failed = レシピがこの入力を受け付けませんでした。理由は欄の横のメッセージを見てください。前回の結果はそのまま残っています。
traj-done = { $ms } ミリ秒でリサンプリングしました。
traj-done-worker = バックグラウンドで { $ms } ミリ秒かけてリサンプリングしました。

traj-exports-title = ダウンロード
traj-download-png = グラフを PNG で保存

traj-key-open = CSV ファイルを開く
traj-key-sample = ラベル付きサンプルを使う
traj-key-download = traj_resampled.csv をダウンロード

traj-explain-title = レシピがすること
traj-explain-input-label = 入力
traj-explain-input = 省略可能な CSV のパス（t_s,q1,q2,...）と dt 秒（既定値 0.02）。
traj-explain-output-label = 出力
traj-explain-output = 等間隔の時刻グリッド上の traj_resampled.csv。
traj-explain-steps-label = 手順
traj-explain-steps = python joint_traj_resample.py または python joint_traj_resample.py your.csv 0.02 を実行し、行数が「長さ ÷ dt」にほぼ等しいことを確かめます。
traj-explain-expected-label = 期待される結果
traj-explain-expected = 不規則なサンプルより行数が増えます。合成サンプルの note 列は、ファイルを差し替えるまで example-row のままです。
traj-explain-interp-title = 線形補間
traj-explain-interp = 新しい各時刻 x について、レシピは x 以前で最後のサンプルを見つけ、次のサンプルまでを直線で結びます（numpy の interp）。グリッドは最初の時刻から始まり、最後の時刻で終わります（最後の時刻がグリッドに乗るよう 1e-12 を足します）。出力の t_s は小数 6 桁、関節の値は 8 桁で、レシピと同じ書き方です。
traj-explain-quirks-title = 注意点
traj-explain-decoding-title = UTF-8 でないファイル
traj-explain-decoding = このページと bsv は同じ方法でファイルを読みます：UTF-8（BOM 付きも可）として読みます。それ以外の文字コードは推測せず、UTF-8 でない最初のバイトのオフセットを示して受け付けません。そのため両者は必ず同じ数値を読みます。
