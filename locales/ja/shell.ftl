# アプリの外枠：ヘッダー、ナビゲーション、言語切り替え、プロジェクターモード、フッター、
# `?` のショートカット一覧、ページが見つからないときの表示、エラー時のバナー。

app-name = BSV Playground
# スマートフォン幅の画面でのブランド表示（読み上げは正式名のまま）。
app-name-short = BSV
app-subtitle = ブラウザで動くロボット工学ドリル

skip-to-content = 本文へ移動

nav-label = ページ
nav-home = ホーム
nav-drills-menu = ドリル
nav-group-kinematics = 運動学
nav-group-dynamics = 動力学と制御
nav-group-trajectories = 軌道
nav-group-planning = 経路計画

lang-switch-title = このページを英語で表示します（キー: L）
projector-toggle = プロジェクター
projector-toggle-title = プロジェクターモード：文字を大きく、線を太く、コントラストを高くします（キー: P）
help-button-label = キーボードショートカット（キー: ?）
help-failed = キーボードショートカットの一覧を読み込めませんでした。接続を確認して、もう一度「?」を押してください。
share-button = 共有
share-button-title = このページのリンクを読み取り用の QR コードで表示します（発表中はキー: S）
share-failed = QR コードを読み込めませんでした。接続を確認して、もう一度お試しください。
share-title = スキャンしてこのページを開く
share-qr-label = このページのリンクの QR コード
share-link-label = またはリンクを入力：
share-too-long = このリンクは長すぎて QR コードにできません。下のリンクを共有してください。

footer-disclaimer = 研究・教育・シミュレーション専用です。ここにあるものは、安全規格に適合した制御器ではなく、実機について判断する根拠にもならず、BSV があなたのロボットを動かしたことを示すものでもありません。実機の扱いは、その所有者またはパートナーに委ねられます。
footer-offline = オフラインで動作します。データがこのページの外に送られることはありません。

overlay-title = キーボードショートカット
overlay-close = 閉じる
overlay-shell-heading = どのページでも
overlay-page-heading = このページ
overlay-page-none = このページ専用のキーはありません。
overlay-access = Tab キーですべての操作部品に移動できます。ドラッグできる図は、フォーカスを当てるとキーでも操作できます（上の一覧のとおり）。グラフの色は色覚の多様性に配慮した Okabe–Ito の配色、ヒートマップは viridis です。OS でアニメーションを減らす設定をオンにしていれば、自動で動き出すものはありません。
overlay-note = 「どこでも」のキーは、入力欄に文字を入力している間は働きません。ページのキーは、ページ本体または図にフォーカスがあるときだけ働き、ボタン・リンク・入力欄にフォーカスがあるときは働きません（先にページをクリックしてください）。ただしロボットパイロットのページでは、アームを動かすキー（と K、R）は、文字を入力中の欄や開いているダイアログを除き、どこにフォーカスがあっても働きます。レッスンの発表中は、リモコンのキーがどこにフォーカスがあっても働きます：PageDown か → で次へ、PageUp か ← で前へ、B か . で画面を黒くして戻し、Esc で終了します（文字を入力中の欄では ← と → はカーソルを動かします）。
key-help = この一覧を表示する／閉じる
key-projector = プロジェクターモードの切り替え
key-lang = 英語と日本語の切り替え
key-escape = この一覧を閉じる
key-sections = ページの次 / 前のセクションへ移動します（プレゼンター用リモコンのボタンが送るキー）。最後のセクションの先は次のドリルです。ステップ実行のあるページでは、ステップを進め / 戻します。

notfound-title = ページが見つかりません
notfound-body = このアドレスのページはありません。古いリンクか、入力まちがいかもしれません。
notfound-home = ホームへ移動

page-mount-failed = このページを開けませんでした。詳しくはブラウザのコンソールを確認してください。
page-loading = このドリルを読み込んでいます…
page-load-failed = このドリルを読み込めませんでした。ネットワークにつながっていないか、アプリのファイルが見つかりません。接続を確認してから、もう一度試してください。
page-load-retry = 再試行

crash-title = 問題が発生しました。
crash-body = 作業内容はアドレス（URL）に残っているので、再読み込みすれば続きから始められます。
crash-reload = ページを再読み込み

# The "next step" chain at the foot of every drill page (the seed's sentences).
chain-label = ドリルの順路
chain-title = 次のステップ
chain-step-pendulum-energy = 振り子のエネルギー
chain-step-ik-workspace = IK ワークスペース
chain-step-traj-resample = 軌道の再サンプリング
chain-step-dh-fk = DH 順運動学
chain-step-jacobian-2r = ヤコビアン掃引
chain-step-cubic-path = 3 次軌道
chain-step-se3-relative = SE(3) 相対姿勢
chain-step-rrt-2d = 2D RRT
chain-step-pid-step = PID ステップ応答
chain-step-manip-grid = 可操作度グリッド
chain-step-trapezoid-profile = 台形速度プロファイル
chain-step-umeyama-2d = Umeyama 位置合わせ
chain-step-teleop = Robot Pilot 練習
chain-step-so101 = ロボットパイロット：SO-101
chain-next-pendulum-energy = 次は平面 IK のワークスペースをサンプリングするか、Robot Pilot で遠隔操作を練習しましょう。
chain-next-ik-workspace = 関節軌道を再サンプリングするか、Robot Pilot で遠隔操作のリセットを練習しましょう。
chain-next-traj-resample = 小さな角度の組で DH 順運動学を計算しましょう。
chain-next-dh-fk = 次は平面 2R のヤコビアンと可操作度の掃引を計算しましょう。
chain-next-jacobian-2r = 次は 2 つの経由点を結ぶ 3 次の関節軌道を作りましょう。
chain-next-cubic-path = 2 つの座標系の相対 SE(3) 姿勢を計算しましょう。
chain-next-se3-relative = 箱形の障害物をよける簡易 2D RRT を実行しましょう。
chain-next-rrt-2d = 次は離散 PID のステップ応答を計算しましょう。
chain-next-pid-step = 次は 2R の可操作度をマップにしましょう。
chain-next-manip-grid = 次は台形速度プロファイルを作りましょう。
chain-next-trapezoid-profile = 次は Umeyama 法で 2D 点群を位置合わせしましょう。
chain-next-umeyama-2d = Robot Pilot Academy を開くか、平面 IK をもう一度試しましょう。
chain-next-teleop = 次はアカデミーのアーム SO-101 を 3D で操縦しましょう。

# The offline install's update offer.
update-ready = BSV Playground の新しいバージョンを利用できます。再読み込みするまでは、今のバージョンのまま動きます。
update-reload = 再読み込みして更新

## レッスンバー：すべてのページの「+ レッスン」と、発表中のバー
lesson-add = + レッスン
lesson-add-title = この画面をレッスンに追加します（レッスンのページで編集できます）
lesson-added = レッスンのステップ { $count } として追加しました。
lesson-added-unsaved = レッスンのステップ { $count } として追加しましたが、このブラウザーの保存領域がいっぱいのため保存されていません。このタブの中だけにあります。
lesson-add-failed = レッスンに画面を追加する機能を読み込めませんでした。接続を確認して、もう一度「+ レッスン」を押してください。
lesson-bar-label = レッスン
lesson-end = レッスンを終える
lesson-next = 次へ →
lesson-page-steps-left = 次のレッスンステップまで、ページをあと { $count } 回進めます
lesson-goals-label = このステップの目標
lesson-goal-below = { $readout } < { $value } { $unit }
lesson-goal-above = { $readout } > { $value } { $unit }
lesson-goal-within = { $readout } が { $value } ± { $tolerance } { $unit } の範囲
lesson-goal-met = ✓ 達成
lesson-goal-open = まだ
lesson-prev = ← 前へ
lesson-step = ステップ
lesson-untitled = 私のレッスン

# 埋め込み表示（`embed=1`）: 同じページと状態を新しいタブで開くリンク。
embed-open = BSV Playground で開く ↗
embed-open-title = このドリルを今の状態のまま新しいタブで開きます
