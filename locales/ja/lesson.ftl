# レッスン：#/lesson ページ、ヘッダーの「この画面を追加」ボタン、発表用バー。

lesson-intro = レッスンは、ページの状態を並べたものです。各ステップにはタイトルと発表者用のメモが付きます。どのページでも、表示を整えてからヘッダーの「+ レッスン」を押すと、今の画面が追加されます。全画面で発表し、Page Down / → で次へ（ステップが求めるときは先にページを進めます）、Page Up / ← で前へ、Esc で終了します。レッスンはこのブラウザーに保存され、リンクや .json ファイルで別の環境に持ち出せます。
lesson-builtin-heading = 組み込みのレッスン（各 10 分ほど）
lesson-builtin-ik-title = IK、ヤコビアン、特異点
lesson-builtin-ik-1-title = IK プレイグラウンド
lesson-builtin-ik-1-note = ひじ下の枝のアーム（このステップのリンクで設定）。先端をドラッグし、どの関節角度ならそこに届くか、もう一方の枝ならひじはどこに来るかを問いかけます。
lesson-builtin-ik-2-title = 伸び切ったアームの近く
lesson-builtin-ik-2-note = q2 = 0.05：アームはほぼまっすぐです。ヒートマップでは白い円が赤い破線 q2 = 0 のすぐ横にあり、その線上ではどこでも |det J| がゼロに落ちます。
lesson-builtin-ik-3-title = ヤコビアンのスイープ
lesson-builtin-ik-3-note = 同じ姿勢で、jacobian-2r の q1 スイープ：σ_min と σ_max。値は q2 だけで決まるので線は平らです。q2 = 0.05 では σ_min がほぼゼロ。小さい σ_min は制御器にとって何を意味するかを問いかけます。
lesson-builtin-ik-4-title = 特異点の近くでの遠隔操作
lesson-builtin-ik-4-note = このステップのリンクで IK 手法を pinv（減衰なし）にしています。アームを伸び切る方向へ動かし、特異点に近づくと関節が急に振れる様子を見せます。DLS が抑えるのはまさにこれです。
lesson-builtin-energy-title = 積分法とエネルギー
lesson-builtin-energy-1-title = 減衰のない振り子
lesson-builtin-energy-1-note = 減衰なし（このステップのリンクで設定）：振り子は毎回同じ高さまで戻ります。速さが最大になるのはどこかを問いかけます。
lesson-builtin-energy-2-title = Euler と RK4
lesson-builtin-energy-2-note = 比較がオン：同じ初期状態からのオイラー法と RK4。誤差のパネルはエネルギー誤差を対数軸で描きます。誤差が増え続けるのはどちらの積分法でしょう？
lesson-builtin-energy-3-title = 大きな時間刻み
lesson-builtin-energy-3-note = h = 0.01 s、既定の 5 倍です（このステップのリンクで設定）。実行全体でのオイラー法の相対エネルギードリフトを、各自が紙かスマートフォンで予想します。「次へ」で、予想の横に真の値と理由が出ます。
lesson-builtin-energy-4-title = フィードバックループ
lesson-builtin-energy-4-note = 1 次系のプラントに PID：出力 y が目標値 r まで上がり、下のパネルは制御出力 u です。オーバーシュートと整定をプロットから読み取ります。
lesson-builtin-planning-title = 経路計画と軌道
lesson-builtin-planning-1-title = RRT を 1 ステップずつ
lesson-builtin-planning-1-note = 5 回押すと木が 5 反復育ちます。各反復でサンプルを引き、最も近いノードを見つけ、そちらへ 1 ステップ伸ばします。10 回に 1 回のサンプルはゴールです。なぜかを問いかけます。
lesson-builtin-planning-2-title = 3 次軌道
lesson-builtin-planning-2-note = 両端で速度ゼロ：速度 qd は中間で最大になり、そこで加速度 qdd がゼロを横切ります。3 次式ではなぜ加速度ゼロからも始められないのかを問いかけます。
lesson-builtin-planning-3-title = 台形プロファイル
lesson-builtin-planning-3-note = 目標：巡航のない、三角形のプロファイルにすること。移動を短くしたり加速度を穏やかにしたりすると平らな部分がどうなるかを問い、クラスに試させます。目標を満たした瞬間に緑になります。
lesson-builtin-planning-4-title = 軌道の再サンプリング
lesson-builtin-planning-4-note = 実際のログは等間隔ではありません。点はファイルのサンプル、線は一定の dt でリサンプリングした系列です。見比べましょう。
lesson-edit-heading = このレッスン
lesson-name-label = レッスンのタイトル
lesson-empty = まだステップがありません。どれかのページを開いて表示を整え、ヘッダーの「+ レッスン」を押すか、上の組み込みレッスンを読み込んでください。
lesson-builtin-shown = これは組み込みのレッスンで、そのまま発表できます（自分のレッスンはまだありません）。編集するか別のものを読み込むと自分のレッスンになります。どのページでも「+ レッスン」を押すと自分の新しいレッスンが始まります。
lesson-present = 発表する
lesson-export = .json を書き出す
lesson-import = .json を読み込む…
lesson-clear = すべてのステップを削除
lesson-link-label = このレッスンへのリンク
lesson-replace-confirm = 今のレッスンを組み込みのレッスンで置き換えますか？残したい場合は先に書き出してください。
lesson-clear-confirm = このレッスンのステップをすべて削除しますか？
lesson-step-up = ↑
lesson-step-up-label = ステップ { $n } を上へ移動
lesson-step-down = ↓
lesson-step-down-label = ステップ { $n } を下へ移動
lesson-step-present = ここから発表
lesson-step-present-label = ここから発表（ステップ { $n }）
lesson-step-delete = 削除
lesson-step-delete-label = ステップ { $n } を削除
lesson-step-title-label = タイトル
lesson-step-note-label = 発表者用のメモ
lesson-step-page-steps-label = 次へ進む前にページを進める回数
lesson-step-focus-label = 画面に出す区画
lesson-step-focus-main = ページのメインビュー
lesson-step-exercise-label = 演習（答えは「次へ」まで隠す）
lesson-step-exercise-none = なし
lesson-step-goals-label = 独自の目標（発表中にリアルタイムで判定。条件は 3 つまで）
lesson-goal-readout-label = 表示値
lesson-goal-op-label = 条件
lesson-goal-op-below = より小さい
lesson-goal-op-above = より大きい
lesson-goal-op-within = ± の範囲内
lesson-goal-value-label = 値
lesson-goal-tolerance-label = 許容幅
lesson-goal-remove = 削除
lesson-goal-add = 目標を追加
lesson-goal-invalid = 数値を入力してください（「範囲内」には 0 以上の許容幅も）。最後に有効だった条件が残ります。
lesson-focus-unknown = ステップ { $step }：ページ「{ $page }」には区画「{ $focus }」がないため、このステップではページのメインビューを表示します。
lesson-page-steps-invalid = 0 から { $max } までの整数を入力してください。
lesson-error-not-text = このファイルはレッスンとして読めませんでした：{ $detail } 今のレッスンはそのまま残ります。
lesson-error-too-big = このファイルは { $size }（{ $bytes } バイト）あります。レッスンのファイルは { $limit } までです。ファイルは読み込んでいません。今のレッスンはそのまま残ります。
lesson-error-empty-file = このファイルは空です。今のレッスンはそのまま残ります。
lesson-error-too-deep = このファイルはリストやオブジェクトの入れ子が { $max } 段を超えています（{ $line } 行目、{ $column } 文字目）。レッスンの入れ子は 3 段です。今のレッスンはそのまま残ります。
lesson-error-not-json = このファイルは JSON ではありません：{ $line } 行目、{ $column } 文字目で読めなくなります。今のレッスンはそのまま残ります。
lesson-error-not-an-object = この JSON ファイルの中身は{ $kind ->
    [array] リスト
    [text] 文字列
    [number] 数値
    [boolean] true か false
    *[other] null
}で、レッスンではありません。今のレッスンはそのまま残ります。
lesson-error-step-not-an-object = ステップ { $step } が、route と title を持つオブジェクトではありません。今のレッスンはそのまま残ります。
lesson-error-no-format = この JSON ファイルは BSV のレッスンではありません：「format」フィールドがありません（レッスンのファイルには "format": "bsv-lesson" があります）。今のレッスンはそのまま残ります。
lesson-error-format = このファイルは BSV のレッスンではありません（形式「{ $found }」、期待される形式は「bsv-lesson」）。今のレッスンはそのまま残ります。
lesson-error-version = このレッスンは別のバージョン（バージョン { $found }）で作られています。このアプリが読めるのはバージョン { $version } です。今のレッスンはそのまま残ります。
lesson-error-unknown-field = レッスンに、このアプリが知らないフィールド「{ $field }」があります。今のレッスンはそのまま残ります。
lesson-error-step-unknown-field = ステップ { $step } に、このアプリが知らないフィールド「{ $field }」があります。今のレッスンはそのまま残ります。
lesson-error-missing-field = レッスンに「{ $field }」フィールドがありません。今のレッスンはそのまま残ります。
lesson-error-step-missing-field = ステップ { $step } に「{ $field }」フィールドがありません。今のレッスンはそのまま残ります。
lesson-error-wrong-type = レッスンのフィールド「{ $field }」は{ $expected ->
    [text] 文字列
    [number] 整数
    *[list] ステップのリスト
}でなければなりません。今のレッスンはそのまま残ります。
lesson-error-step-wrong-type = ステップ { $step }、フィールド「{ $field }」：{ $expected ->
    [text] 文字列
    [number] 整数
    *[list] リスト
}でなければなりません。今のレッスンはそのまま残ります。
lesson-error-no-steps = このレッスンにはステップがなく、発表するものがありません。今のレッスンはそのまま残ります。
lesson-error-too-many-steps = レッスンのステップは { $max } 個までです。このレッスンには { $count } 個あります。今のレッスンはそのまま残ります。
lesson-error-unknown-page = ステップ { $step }、フィールド「route」：このアプリに「{ $page }」というページはありません。今のレッスンはそのまま残ります。
lesson-error-too-long = ステップ { $step }、フィールド「{ $field }」：{ $max } 文字を超えています。今のレッスンはそのまま残ります。
lesson-error-page-steps = ステップ { $step }、フィールド「pageSteps」：0 から { $max } までの整数でなければなりません。今のレッスンはそのまま残ります。
lesson-error-unknown-exercise = ステップ { $step }、フィールド「exercise」：ページ「{ $page }」に「{ $exercise }」という演習はありません。今のレッスンはそのまま残ります。
lesson-error-goal = ステップ { $step }、目標 { $goal }：目標は最大 { $max } 個の条件で、それぞれページの表示値、「<」「>」または「within」、数値、そして「within」には 0 以上の許容幅です。今のレッスンはそのまま残ります。
lesson-error-title-too-long = レッスンのフィールド「title」が { $max } 文字を超えています。今のレッスンはそのまま残ります。
lesson-unsaved = このレッスンは保存されていません：このブラウザーの保存領域がいっぱいです（または保存が無効です）。タブを開いている間はこのページに残ります。残すには .json に書き出してください。
lesson-unreadable = このブラウザーに保存されていたレッスンが読めなかったため（手で編集された、または途中で切れている）、このページは空の状態から始めました。そのテキストはこのブラウザーの保存領域に { $key } として残してあります。
lesson-unreadable-download = 残したテキストをダウンロード
lesson-unreadable-forget = 破棄する
lesson-present-two = 2 画面で発表する
present-two-blocked = ブラウザーが 2 つ目のウィンドウを開かせませんでした。このサイトのポップアップを許可してから、もう一度「2 画面で発表する」を押してください。
lesson-present-failed = 発表用のコードを取得できませんでした。接続を確かめて、もう一度お試しください。
present-two-label = 発表者ビュー
present-two-now = 現在
present-two-next = 次
present-two-last = レッスンの終わり
present-two-elapsed = 開始からの経過時間
present-two-picture = 次のステップ: { $title }
present-two-black = 画面を黒くする
present-two-unblack = 画面を戻す
present-two-blacked = 会場の画面は黒です(B または . で戻ります)。
