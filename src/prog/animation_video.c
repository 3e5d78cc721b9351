/* The animation's video (animation.c): ffmpeg encoding raw frames read from a pipe, and what must
 * not outlive the program on any exit path - an error, or SIGINT/SIGTERM/SIGHUP: the ffmpeg child
 * (stopped and waited for), its temporary video and a frame being written (removed). */
#define _POSIX_C_SOURCE 200809L
#include "animation_video.h"

#include "atomic_file.h"

#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <sys/wait.h>
#include <unistd.h>

static volatile pid_t video_pid = -1; /* the running ffmpeg, or -1 */
static char video_tmp[4200];          /* the video ffmpeg writes, renamed on success */

/* Async-signal-safe: kill(), waitpid(), unlink(). SIGKILL, not SIGTERM: on SIGTERM ffmpeg
 * finishes its output file, which could then appear after the unlink. */
static void on_signal(int sig)
{
    if (video_pid > 0) {
        kill(video_pid, SIGKILL);
        waitpid(video_pid, NULL, 0);
    }
    if (video_tmp[0])
        unlink(video_tmp);
    sus_sys_atomic_file_remove_temporaries(); /* a frame being written (named fallback) */
    signal(sig, SIG_DFL);
    raise(sig);
}

/* atexit: on an error exit the video is unfinished; stop ffmpeg, wait for it, remove its file. */
static void stop_video(void)
{
    if (video_pid > 0) {
        kill(video_pid, SIGKILL);
        waitpid(video_pid, NULL, 0);
        video_pid = -1;
    }
    if (video_tmp[0])
        unlink(video_tmp);
    video_tmp[0] = '\0';
}

/* ffmpeg reading raw frames on a pipe; returns the write end as a stream, or NULL. */
static FILE *start_video(int W, int H, int fps, const char *out)
{
    int fd[2];
    if (pipe(fd) != 0)
        return NULL;
    char size[32], rate[16];
    snprintf(size, sizeof size, "%dx%d", W, H);
    snprintf(rate, sizeof rate, "%d", fps);
    const pid_t pid = fork();
    if (pid == 0) {
        dup2(fd[0], 0);
        close(fd[0]);
        close(fd[1]);
        /* x264's veryfast preset at crf 21 keeps its default preset's fidelity to the frames (PSNR)
         * in much less encoding time, for a somewhat larger file: after figure_stability, the
         * video is the largest part of the CPU time of make figures */
        execlp("ffmpeg", "ffmpeg", "-y", "-loglevel", "error", "-f", "rawvideo", "-pixel_format",
               "bgra", "-video_size", size, "-framerate", rate, "-i", "-", "-c:v", "libx264",
               "-preset", "veryfast", "-crf", "21", "-pix_fmt", "yuv420p", out, (char *)NULL);
        _exit(127);
    }
    close(fd[0]);
    if (pid < 0) {
        close(fd[1]);
        return NULL;
    }
    video_pid = pid;
    fcntl(fd[1], F_SETFD, FD_CLOEXEC);
    return fdopen(fd[1], "w");
}

/* Closes the pipe and waits: 0 when ffmpeg exited with status 0. */
static int finish_video(FILE *video)
{
    fclose(video);
    int status = -1;
    const pid_t pid = video_pid;
    if (pid > 0 && waitpid(pid, &status, 0) != pid)
        status = -1;
    video_pid = -1;
    return WIFEXITED(status) && WEXITSTATUS(status) == 0 ? 0 : -1;
}

void suslov_video_guard(void)
{
    /* A dead ffmpeg must show as a write error, not kill us by SIGPIPE with its file left. */
    signal(SIGPIPE, SIG_IGN);
    atexit(stop_video);
    const int sigs[3] = {SIGINT, SIGTERM, SIGHUP};
    for (int i = 0; i < 3; i++) {
        struct sigaction sa = {.sa_handler = on_signal};
        sigemptyset(&sa.sa_mask);
        sigaction(sigs[i], &sa, NULL);
    }
}

/* The video, through ffmpeg's standard input, when ffmpeg is there; NULL otherwise. */
FILE *suslov_video_open(int W, int H, int fps, const char *figdir, const char *mp4)
{
    FILE *video = NULL;
    const int want_video = getenv("SUSLOV_NO_VIDEO") == NULL;
    if (want_video && system("command -v ffmpeg >/dev/null 2>&1") == 0) {
        snprintf(video_tmp, sizeof video_tmp, "%s/attitude.tmp.%ld.mp4", figdir, (long)getpid());
        video = start_video(W, H, fps, video_tmp);
        if (!video)
            fprintf(stderr, "animation: cannot start ffmpeg: frames written, no %s\n", mp4);
    } else if (want_video) {
        fprintf(stderr, "animation: ffmpeg is not installed: frames written, no %s\n", mp4);
    }
    return video;
}

void suslov_video_close(FILE *video, const char *mp4)
{
    if (!video)
        return;
    if (finish_video(video) == 0 && rename(video_tmp, mp4) == 0) {
        video_tmp[0] = '\0';
    } else {
        stop_video();
        fprintf(stderr, "animation: ffmpeg failed; no video\n");
    }
}

void suslov_video_frame(FILE **video, const uint32_t *px, int W, int H)
{
    if (*video && fwrite(px, sizeof(uint32_t), (size_t)W * H, *video) != (size_t)W * H) {
        finish_video(*video);
        *video = NULL;
        stop_video();
        fprintf(stderr, "animation: ffmpeg stopped reading; no video\n");
    }
}
