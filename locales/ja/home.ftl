# ホームページ：BSV ページの見出しと紹介文、ブラウザで動く注目のツール、各レシピのカード
# （レシピ自体の文言は recipes.ftl にある）。

home-headline = ロボティクス：シミュレーションし、サンプリングし、記録する。そして遠隔操作の練習へ

# 冒頭で動かせるアームと、各ページのタイルが示すもの。
home-tiles-label = ブラウザで動くドリル
home-arm-label = 届く範囲の輪の中にある 2 リンクのアーム（L1 0.12 m、L2 0.10 m）
home-arm-hint = オレンジの先端をドラッグすると、逆運動学で両方の関節がついてきます。リンクをドラッグすると 1 つの関節だけが回ります。
home-arm-key-nudge = ホームのアームにフォーカスがあるとき、先端を 5 mm 動かす（Shift：1 mm）
home-arm-open = この姿勢を IK プレイグラウンドで開く
home-card-more = 入力・出力ファイル・コマンドライン
home-featured-label-ik-2r = 運動学・アームを動かして |det J| の変化を見る
home-featured-label-dh-fk = 運動学・DH チェーンを 3D で 1 行ずつ
home-featured-label-se3-relative = 運動学・ある座標系から見た別の座標系
home-featured-label-umeyama-2d = 運動学・点群に回転・スケール・並進を合わせる
home-featured-label-pendulum-energy = 動力学・エネルギーのずれ（Euler と RK4）
home-featured-label-pid-step = 制御・ステップ応答で Kp・Ki・Kd を調整
home-featured-label-cubic-path = 軌道・3 次の動きとその速度・加速度
home-featured-label-trapezoid-profile = 軌道・台形が三角形になるとき
home-featured-label-traj-resample = 軌道・関節ログを新しい周期でリサンプリング
home-featured-label-rrt-2d = 経路計画・ランダムな木がゴールへ伸びる
home-featured-label-teleop = 遠隔操作の練習・アームを操作して 10 回記録する
home-featured-label-so101 = 3D の遠隔操作・SO-101 を Isaac Lab と同じ操作で動かす
home-featured-label-drills = 全レシピ・自分の値で、同じ CSV ファイルを
home-featured-label-lesson = 授業・画面をつないでレッスンにし、発表する
home-featured-label-class = 授業・クラスの進み具合のファイルを集める

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
home-card-pairs-umeyama-2d = Umeyama 法のページと組み合わせて使えます。点と真の変換をドラッグし、重心、共分散、特異値分解、鏡映の補正、スケール、並進を一歩ずつ確かめられます。
home-card-pairs-dh-fk = DH のページと組み合わせて使えます。3D でチェーンの関節を回し、視点を回しながら、1 行を 4 つの基本変換に分けてたどれます。
home-card-pairs-se3-relative = 相対姿勢のページと組み合わせて使えます。フレーム A や B を 3D でドラッグし、ラジアンと度を切り替え、同じ角度を内因的・外因的な回転として見比べられます。

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

# The seed's "Compare the tools" table (outbound links only; nothing is fetched).
home-tools-title = ツールの比較
home-tools-intro = 難易度は、最初のプロジェクトを想定した BSV 独自の評価です。何かを公開する前に、各ライセンスを公式ページで確認してください。リンク先は公式サイトです。このアプリが何かを取得することはありません。
home-tools-caption = ドリルが参照するツール：用途・ライセンス・難易度・実行場所
home-tools-col-tool = ツール
home-tools-col-job = 用途
home-tools-col-licence = ライセンス
home-tools-col-difficulty = 難易度
home-tools-col-where = ローカル / クラウド
home-tools-external = （公式サイト、アプリの外で開きます）
home-tool-mujoco-name = MuJoCo
home-tool-mujoco-job = 振り子のレシピで使う剛体シミュレーション
home-tool-mujoco-licence = Apache-2.0
home-tool-mujoco-difficulty = 中級
home-tool-mujoco-where = ローカル
home-tool-mujoco-docs-name = MuJoCo ドキュメント
home-tool-mujoco-docs-job = モデル形式・センサー・アクチュエーター
home-tool-mujoco-docs-licence = Apache-2.0
home-tool-mujoco-docs-difficulty = 中級
home-tool-mujoco-docs-where = ローカル
home-tool-numpy-name = NumPy
home-tool-numpy-job = IK のグリッドや軌道計算のための配列
home-tool-numpy-licence = BSD-3-Clause
home-tool-numpy-difficulty = 初級
home-tool-numpy-where = ローカル
home-tool-isaac-lab-name = Isaac Lab ドキュメント
home-tool-isaac-lab-job = Isaac Lab の公式インストール手順
home-tool-isaac-lab-licence = Apache-2.0（ドキュメント）
home-tool-isaac-lab-difficulty = 上級
home-tool-isaac-lab-where = クラウド / Web API
home-tool-isaac-teleop-name = Isaac Capture（遠隔操作ドキュメント）
home-tool-isaac-teleop-job = 公式の遠隔操作ドキュメント（NVIDIA、Isaac Capture）
home-tool-isaac-teleop-licence = Apache-2.0（ドキュメントサイト）
home-tool-isaac-teleop-difficulty = 上級
home-tool-isaac-teleop-where = クラウド / Web API
home-tool-ros2-name = ROS 2 ドキュメント
home-tool-ros2-job = スクリプトだけの段階を超えたときのロボット用ミドルウェア
home-tool-ros2-licence = Apache-2.0 / パッケージによって異なるオープンライセンス
home-tool-ros2-difficulty = 中級
home-tool-ros2-where = ローカル + クラウド
home-tool-robot-web-tools-name = Robot Web Tools
home-tool-robot-web-tools-job = ブラウザーと ROS をつなぐブリッジ（BSV のレシピとは別物）
home-tool-robot-web-tools-licence = BSD-3-Clause
home-tool-robot-web-tools-difficulty = 中級
home-tool-robot-web-tools-where = クラウド / Web API

# タイルとカードのコードを読み込む間、その場所に出す行と、読み込めなかったときの行。
home-more-loading = ドリルのタイルとレシピのカードを読み込んでいます…
home-more-failed = ドリルのタイルとレシピのカードを読み込めませんでした。ネットワークにつながっていません。接続を確かめてから、もう一度お試しください。
