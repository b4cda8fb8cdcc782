# ページキットの部品（src/ui/kit）のメッセージ。ID は `kit-` で始まる。

## URL の状態の通知（kit::url_state）
kit-url-unknown = このリンクには、このページにない設定が含まれていたため無視しました：{ $keys }。
kit-url-invalid = リンクの次の設定は使えなかったため、既定値のままです：{ $keys }。
kit-url-flagged = このリンクの値の一部が正しくありません（{ $keys }）。理由は各欄の横のメッセージを見てください。
kit-url-file = このリンクではファイル「{ $name }」が使われていました。実行するには、もう一度開いてください。

## ステッパー（kit::stepper）
kit-stepper-label = ステップ実行
kit-stepper-start = 最初へ（Home）
kit-stepper-back = 1 ステップ戻る（← または Page Up）
kit-stepper-run = 再生（Space）
kit-stepper-pause = 一時停止（Space）
kit-stepper-step = 1 ステップ進む（→ または Page Down）
kit-stepper-end = 最後へ（End）
kit-stepper-reset = 最初からやり直す（R）
kit-stepper-speed = 速さ
kit-stepper-speed-rate = 毎秒 { $rate } ステップ
kit-stepper-speed-max = できるだけ速く
kit-stepper-scrub = 位置
kit-stepper-position = { $len } ステップ中 { $index }
kit-stepper-position-open = ステップ { $index }
kit-stepper-key-step = 1 ステップ進む
kit-stepper-key-back = 1 ステップ戻る（正確に）
kit-stepper-key-run = 再生・一時停止
kit-stepper-key-ends = 最初へ／最後へ
kit-stepper-key-reset = 最初からやり直す

## Parameter form (kit::form)
kit-form-args = 引数（コマンドラインでの順番）
kit-form-options = オプション
kit-form-options-note = bsv コマンドだけにある追加の設定です。Python のレシピにはオプションがなく、常にこの既定値を使います。
kit-form-default = 既定値：
kit-form-involved = この値は「{ $field }」と同じ制限にかかわっています。
kit-form-file-open = CSV ファイルを開く…
kit-form-file-sample = 内蔵のラベル付きサンプルを使う

## Exports: downloads and command lines (kit::exports)
kit-exports-download = { $file } をダウンロード
kit-exports-download-failed = { $file } を保存できませんでした：{ $error }
kit-exports-title = 同じ実行をコマンドラインで
kit-exports-hint = どちらの行をターミナルで実行しても、同じファイルが得られます（Python のレシピには Python 3 と必要なライブラリが、bsv にはこのプロジェクトのコマンドラインツールが必要です）。
kit-exports-python = Python のレシピ
kit-exports-bsv = BSV のコマンドライン
kit-exports-copy = コピー
kit-exports-copied = コマンドをクリップボードにコピーしました。
kit-exports-copy-failed = このブラウザではコピーが許可されていません。コマンドを選択して Ctrl+C（Mac では ⌘C）を押してください。
kit-exports-python-no-options = Python のレシピにはオプションがないため、この行には { $options } が含まれず、既定値での結果になります。この実行を再現できるのは bsv の行だけです。
kit-exports-file-note = これらのコマンドは、{ $name } があるフォルダーで実行してください。

# ページキットの部品（src/ui/kit）のメッセージ。ID は `kit-` で始めます。

## 長い実行の進捗パネル（kit::progress）
kit-progress-label = 実行の進捗
kit-progress-starting = 開始しています…
kit-progress-rows = { $total } 行中 { $done } 行（{ $percent } %）
kit-progress-time = 経過 { $elapsed }
kit-progress-time-left = 経過 { $elapsed }、残り約 { $left }
kit-progress-seconds = { $s } 秒
kit-progress-minutes = { $min } 分 { $s } 秒
kit-progress-cancel = キャンセル

## バックグラウンドでの長い実行（kit::worker）
kit-worker-failed = バックグラウンドの実行が予期せず止まりました（{ $detail }）。もう一度実行してください。繰り返し失敗する場合は、ページを再読み込みしてください。

## 3D ビュー（kit::orbit）
kit-orbit-presets = 視点の切り替え
kit-orbit-view-iso = 斜め
kit-orbit-view-top = 上
kit-orbit-view-front = 正面
kit-orbit-view-side = 側面
kit-orbit-hint-mouse = マウス：ドラッグで回転、ホイールで拡大縮小。
kit-orbit-hint-touch = タッチ：横にドラッグで回転、ピンチで拡大縮小。
kit-orbit-hint-keys = キー（ビュー選択中）：矢印で回転、+ / − で拡大縮小。
kit-orbit-key-orbit = 3D ビューの視点を回す（ビューにフォーカスがあるとき。Shift で大きく）
kit-orbit-key-zoom = 3D ビューの拡大・縮小（ビューにフォーカスがあるとき）

# キットのレイアウトで作るページ（信号のページ、Umeyama）の節の見出し。
signals-params-title = パラメータ
signals-explain-title = このページで見ているもの
signals-quirks-title = この移植版がレシピの代わりに決めていること
signals-exports-title = ダウンロードとコマンドライン
