# Comparison only (not a dependency of ergocell or CI): writes calibration/tests/data/opencv_corners.csv,
# OpenCV's corners on the stereo sample, used by calibration/tests/opencv_sample.rs.
import cv2, numpy as np
import os
d = os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../shared/data/opencv-stereo-sample/")
crit = (cv2.TERM_CRITERIA_EPS + cv2.TERM_CRITERIA_MAX_ITER, 30, 0.01)
out = open(os.path.join(os.path.dirname(os.path.abspath(__file__)), "../calibration/tests/data/opencv_corners.csv"), "w")
out.write("# OpenCV %s findChessboardCorners((9,6)) + cornerSubPix(winSize=(5,5), i.e. an 11x11 px window, 30 it, 0.01) on ../shared/data/opencv-stereo-sample\n" % cv2.__version__)
out.write("image,index,u,v\n")
for side in ["left", "right"]:
    for n in ["01","02","03","04","05","06","07","08","09","11","12","13","14"]:
        g = cv2.imread(d + f"{side}{n}.jpg", 0)
        ok, c = cv2.findChessboardCorners(g, (9, 6))
        c = cv2.cornerSubPix(g, c, (5, 5), (-1, -1), crit)
        for i, p in enumerate(c.reshape(-1, 2)):
            out.write(f"{side}{n},{i},{p[0]:.4f},{p[1]:.4f}\n")
