/* A Cyclone DDS (Debian's libddsc0debian, with its DDS Security plugins) peer for ergocell's SROS2
 * check: publishes ergocell_msgs/CameraLandmarks on one topic for a while, as a camera would. Security
 * comes from CYCLONEDDS_URI (the enclave's files); without it the peer runs unsecured.
 * Usage: peer <dds topic> <camera_id> <seconds>
 * Exit: 0 published, 2 no participant (e.g. the identity was refused), 3 the writer was refused (the
 * permissions do not allow the topic). */
#include <stdio.h>
#include <stdlib.h>
#include "dds/dds.h"
#include "CameraLandmarks.h"

int main(int argc, char **argv) {
  if (argc != 4) { fprintf(stderr, "usage: peer <dds topic> <camera_id> <seconds>\n"); return 1; }
  dds_entity_t p = dds_create_participant(DDS_DOMAIN_DEFAULT, NULL, NULL);
  if (p < 0) { printf("participant refused: %s\n", dds_strretcode(-p)); return 2; }
  dds_entity_t t = dds_create_topic(p, &ergocell_msgs_msg_dds__CameraLandmarks__desc, argv[1], NULL, NULL);
  if (t < 0) { printf("topic refused: %s\n", dds_strretcode(-t)); return 3; }
  dds_qos_t *q = dds_create_qos();
  dds_qset_reliability(q, DDS_RELIABILITY_BEST_EFFORT, 0);
  dds_entity_t w = dds_create_writer(p, t, q, NULL);
  dds_delete_qos(q);
  if (w < 0) { printf("writer refused: %s\n", dds_strretcode(-w)); return 3; }
  static float xs[33], ys[33], vis[33], pres[33];
  for (int i = 0; i < 33; i++) { xs[i] = 100.0f + i; ys[i] = 200.0f + i; vis[i] = 0.9f; pres[i] = 0.9f; }
  ergocell_msgs_msg_dds__CameraLandmarks_ m = {0};
  m.header.frame_id = argv[2];
  m.camera_id = argv[2];
  m.image_width = 1280; m.image_height = 720;
  m.x_px._buffer = xs; m.x_px._length = m.x_px._maximum = 33;
  m.y_px._buffer = ys; m.y_px._length = m.y_px._maximum = 33;
  m.visibility._buffer = vis; m.visibility._length = m.visibility._maximum = 33;
  m.presence._buffer = pres; m.presence._length = m.presence._maximum = 33;
  int n = (int)(atof(argv[3]) * 30.0), sent = 0;
  for (int k = 0; k < n; k++) {
    dds_time_t now = dds_time();
    m.header.stamp.sec = (int32_t)(now / DDS_NSECS_IN_SEC);
    m.header.stamp.nanosec = (uint32_t)(now % DDS_NSECS_IN_SEC);
    if (dds_write(w, &m) == DDS_RETCODE_OK) sent++;
    dds_sleepfor(DDS_MSECS(33));
  }
  printf("published %d messages on %s\n", sent, argv[1]);
  dds_delete(p);
  return 0;
}
