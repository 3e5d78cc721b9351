/* The animation's video (animation_video.c): its frames piped to ffmpeg, which writes a
 * temporary file renamed into place when it succeeds; on any exit path - an error, or
 * SIGINT/SIGTERM/SIGHUP - ffmpeg is stopped and waited for and the temporary files removed. */
#ifndef SUSLOV_ANIMATION_VIDEO_H
#define SUSLOV_ANIMATION_VIDEO_H

#include <stdint.h>
#include <stdio.h>

/* Installs that clean-up (at exit and on the three signals), and ignores SIGPIPE: a dead ffmpeg
 * must show as a write error, not kill the program with its file left. */
void suslov_video_guard(void);
/* ffmpeg encoding W x H frames at fps into figdir's temporary, when it is installed and
 * SUSLOV_NO_VIDEO is unset: the stream that takes the frames, or NULL (said on stderr, except
 * under SUSLOV_NO_VIDEO). */
FILE *suslov_video_open(int W, int H, int fps, const char *figdir, const char *mp4);
/* One frame of BGRA pixels; when ffmpeg stops reading, the video is given up (said) and *video
 * set to NULL. Nothing when *video is NULL. */
void suslov_video_frame(FILE **video, const uint32_t *px, int W, int H);
/* Waits for ffmpeg and renames its file to mp4; on failure removes it (said). Nothing for NULL. */
void suslov_video_close(FILE *video, const char *mp4);

#endif
