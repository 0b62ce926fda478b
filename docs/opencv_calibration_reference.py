# Comparison only: OpenCV's numbers on the same images (not a dependency of ergocell or of CI).
# pip install opencv-python-headless numpy; python3 docs/opencv_calibration_reference.py [winSize] [threads]
# winSize: cornerSubPix half-window (5 = an 11x11 px window like ergocell's; 11 = stereo_calib.cpp's).
import cv2, numpy as np, glob, time, sys
import os
d = os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../shared/data/opencv-stereo-sample/")
pat = (9, 6); sq = 0.025
obj = np.zeros((54, 3), np.float32); obj[:, :2] = np.mgrid[0:9, 0:6].T.reshape(-1, 2) * sq
crit = (cv2.TERM_CRITERIA_EPS + cv2.TERM_CRITERIA_MAX_ITER, 30, 0.01)
def run(win=5):
    L, R = [], []
    for n in ["01","02","03","04","05","06","07","08","09","11","12","13","14"]:
        gl = cv2.imread(d+f"left{n}.jpg", 0); gr = cv2.imread(d+f"right{n}.jpg", 0)
        okl, cl = cv2.findChessboardCorners(gl, pat); okr, cr = cv2.findChessboardCorners(gr, pat)
        if okl and okr:
            cl = cv2.cornerSubPix(gl, cl, (win, win), (-1, -1), crit); cr = cv2.cornerSubPix(gr, cr, (win, win), (-1, -1), crit)
            L.append(cl); R.append(cr)
        else:
            print("skip", n, okl, okr)
    O = [obj] * len(L)
    rl, Kl, Dl, _, _ = cv2.calibrateCamera(O, L, (640, 480), None, None)
    rr, Kr, Dr, _, _ = cv2.calibrateCamera(O, R, (640, 480), None, None)
    rs, _, _, _, _, Rm, T, _, _ = cv2.stereoCalibrate(O, L, R, Kl, Dl, Kr, Dr, (640, 480), flags=cv2.CALIB_FIX_INTRINSIC)
    return len(L), (rl, Kl, Dl), (rr, Kr, Dr), (rs, Rm, T)
import sys
WIN=int(sys.argv[1]) if len(sys.argv)>1 else 5
if len(sys.argv)>2: cv2.setNumThreads(int(sys.argv[2]))
res = run(WIN)
runs = [];
for _ in range(5):
    a = time.perf_counter(); run(WIN); runs.append(time.perf_counter() - a)
n, (rl, Kl, Dl), (rr, Kr, Dr), (rs, Rm, T) = res
np.set_printoptions(precision=6, suppress=True)
print("opencv", cv2.__version__, "pairs", n, "cornerSubPix winSize", WIN)
for name, r, K, D in [("left", rl, Kl, Dl), ("right", rr, Kr, Dr)]:
    print(f"{name}: fx={K[0,0]:.3f} fy={K[1,1]:.3f} cx={K[0,2]:.3f} cy={K[1,2]:.3f} rms={r:.4f} dist={D.ravel()}")
print(f"stereo rms={rs:.4f} T={T.ravel()} baseline_mm={np.linalg.norm(T)*1000:.3f} rvec={cv2.Rodrigues(Rm)[0].ravel()}")
print(f"threads {cv2.getNumThreads()}: time full stereo calibration (detect+subpix+2 intrinsics+stereo): median of 5 = {sorted(runs)[2]*1000:.1f} ms")
