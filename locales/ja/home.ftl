# ホームページ：BSV ページの見出しと紹介文、ブラウザで動く注目のツール、各レシピのカード
# （レシピ自体の文言は recipes.ftl にある）。

home-page-title = ホーム
home-headline = ロボティクス：シミュレーションし、サンプリングし、記録する。そして遠隔操作の練習へ
home-intro = 短く、ごまかしのないシミュレーション演習を組み立てましょう。題材は MuJoCo のエネルギー、平面 IK、軌道のリサンプリング、DH 順運動学、ヤコビアンと可操作度、3 次の関節経路、SE(3) の相対姿勢、そして簡易版の 2D RRT です。Isaac Teleop による遠隔操作の練習には Robot Pilot Academy を使ってください。BSV は NVIDIA のコードを再配布していません。
home-featured-label = ブラウザで動くインタラクティブなツール（英語／日本語）
home-featured-open = プレイグラウンドを開く
home-recipes-heading = 演習レシピ
home-recipes-intro = BSV の Python レシピを Rust で作り直した、12 の短い演習です。コマンドラインの「bsv <レシピ ID>」は、Python スクリプトと同じ値を受け取り、同じ CSV ファイルを書き出します。
home-card-inputs = 入力と既定値
home-card-writes = 出力ファイル
home-card-options = オプション
home-card-cli = コマンドライン
home-card-python = 元の Python
home-card-drill = このドリルを実行する
home-card-in-browser = ブラウザで試す：
home-card-pairs-ik-2r = IK プレイグラウンド（BSV の元の資料では「IK Field Lab」と呼ばれているもの）と組み合わせて使えます。そこでアームを動かすと |det J| の変化が見られます。
home-card-pairs-traj-resample = 専用のページでそのまま動かせます。CSV を開くかドロップすると、各関節のリサンプリング結果が見られます。
home-card-pairs-cubic-path = 3 次経路のページと組み合わせて使えます。終点と終了時刻をドラッグすると、速度と加速度の変化が見られます。
home-card-pairs-pid-step = PID ステップ応答のページと組み合わせて使えます。前のゲインの残像と並べて、Kp・Ki・Kd をその場で調整できます。
home-card-pairs-trapezoid-profile = 台形プロファイルのページと組み合わせて使えます。vmax と amax をドラッグし、動きが三角形になる境目を確かめられます。
home-card-pairs-pendulum-energy = 振り子のページと組み合わせて使えます。振れる様子を見ながら、Euler と RK4 を並べてエネルギーのずれを比べられます。
home-card-pairs-rrt-2d = RRT ステッパーと組み合わせて使えます。自分で描いた環境で、木を 1 反復ずつ（逆向きにも）成長させられます。

# The picture on each recipe card (drawn from the kernel at the defaults), for screen readers.
home-picture-pendulum-energy = 既定の振り子の運動エネルギー・位置エネルギー・全エネルギーの時間変化
home-picture-ik-workspace = 既定の 2R ワークスペースのグリッドで届く点（届かない点は灰色）
home-picture-traj-resample = ラベル付きサンプル軌道：元の点を点で、再サンプリングした関節を線で表示
home-picture-dh-fk = 既定の 3R チェーンを地面のグリッドの上に 3D で描いた図
home-picture-jacobian-2r = 既定のヤコビアン掃引での先端位置（q2 を固定して q1 を回す）を上から見た図
home-picture-cubic-path = 既定の 3 次軌道の位置と速度の時間変化
home-picture-se3-relative = 既定の座標系 A と B を色付きの軸で描き、A から B への矢印を添えた図
home-picture-rrt-2d = 単位正方形の中の既定の RRT の木と、見つかった経路（オレンジ）
home-picture-pid-step = 既定の PID ステップ応答の目標値と出力の時間変化
home-picture-manip-grid = (q1, q2) グリッド上の可操作度のカラーマップ（明るいほど高い）
home-picture-trapezoid-profile = 既定の台形速度プロファイルの速度の時間変化
home-picture-umeyama-2d = 既定の Umeyama の元の点・ノイズ付きの目標点・位置合わせ後の点と残差
