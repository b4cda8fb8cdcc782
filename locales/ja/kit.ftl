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
