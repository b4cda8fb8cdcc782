# アプリの外枠：ヘッダー、ナビゲーション、言語切り替え、プロジェクターモード、フッター、
# `?` のショートカット一覧、ページが見つからないときの表示、エラー時のバナー。

app-name = BSV Playground
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

footer-disclaimer = 研究・教育・シミュレーション専用です。ここにあるものは、安全規格に適合した制御器ではなく、実機について判断する根拠にもならず、BSV があなたのロボットを動かしたことを示すものでもありません。実機の扱いは、その所有者またはパートナーに委ねられます。
footer-offline = オフラインで動作します。データがこのページの外に送られることはありません。

overlay-title = キーボードショートカット
overlay-close = 閉じる
overlay-shell-heading = どのページでも
overlay-page-heading = このページ
overlay-page-none = このページ専用のキーはありません。
overlay-note = 「どこでも」のキーは、入力欄に文字を入力している間は働きません。ページのキーは、ページ本体または図にフォーカスがあるときだけ働き、ボタン・リンク・入力欄にフォーカスがあるときは働きません（先にページをクリックしてください）。ページが一覧に載せていないキー（プレゼンター用リモコンの Page Up / Page Down、B、. など）は、ブラウザーとプレゼンテーションソフトに任せます。
key-help = この一覧を表示する／閉じる
key-projector = プロジェクターモードの切り替え
key-lang = 英語と日本語の切り替え
key-escape = この一覧を閉じる

notfound-title = ページが見つかりません
notfound-body = このアドレスのページはありません。古いリンクか、入力まちがいかもしれません。
notfound-home = ホームへ移動

page-mount-failed = このページを開けませんでした。詳しくはブラウザのコンソールを確認してください。

crash-title = 問題が発生しました。
crash-body = 作業内容はアドレス（URL）に残っているので、再読み込みすれば続きから始められます。
crash-reload = ページを再読み込み
