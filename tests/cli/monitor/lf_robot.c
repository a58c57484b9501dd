/* A host stand-in for a line-following robot that runs the line follower engine built with
   --trace: the sensors' values come from a CSV file (gfec run's --inputs format, a row a tick),
   and each tick's frame goes to stdout or, with --listen PORTFILE, to the one client that
   connects to a TCP port on 127.0.0.1 (written to PORTFILE once listening), as a robot on a
   network would serve it. --pause-after N S: sleep S seconds after tick N (a link gone quiet). */
#define _POSIX_C_SOURCE 200809L
#include "lf.h"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <unistd.h>

static int sensors[4];
static int out_fd = 1;

bool Left_IR_Black(void) { return sensors[0] != 0; }
bool Left_IR_White(void) { return sensors[1] != 0; }
bool Right_IR_Black(void) { return sensors[2] != 0; }
bool Right_IR_White(void) { return sensors[3] != 0; }
void Left_FW(void) {}
void Left_Stop(void) {}
void Right_FW(void) {}
void Right_Stop(void) {}

void LineFollower_trace_write(const unsigned char *data, unsigned len)
{
    size_t done = 0;
    while (done < len) {
        ssize_t n = write(out_fd, data + done, len - done);
        if (n <= 0) exit(3);
        done += (size_t)n;
    }
}

static int listen_once(const char *port_file)
{
    struct sockaddr_in a;
    socklen_t size = sizeof a;
    int s = socket(AF_INET, SOCK_STREAM, 0), c;
    FILE *f;
    memset(&a, 0, sizeof a);
    a.sin_family = AF_INET;
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    if (s < 0 || bind(s, (struct sockaddr *)&a, sizeof a) != 0 || listen(s, 1) != 0 ||
        getsockname(s, (struct sockaddr *)&a, &size) != 0) exit(4);
    f = fopen(port_file, "w");
    if (f == NULL) exit(4);
    fprintf(f, "%d\n", ntohs(a.sin_port));
    fclose(f);
    c = accept(s, NULL, NULL);
    close(s);
    if (c < 0) exit(4);
    return c;
}

int main(int argc, char **argv)
{
    LineFollower m;
    char line[256];
    FILE *csv;
    long tick = 0, pause_after = -1, pause_s = 0;
    int i;
    if (argc < 2) return 2;
    for (i = 2; i < argc; ++i) {
        if (strcmp(argv[i], "--listen") == 0 && i + 1 < argc) out_fd = listen_once(argv[++i]);
        else if (strcmp(argv[i], "--pause-after") == 0 && i + 2 < argc) {
            pause_after = atol(argv[++i]);
            pause_s = atol(argv[++i]);
        } else return 2;
    }
    csv = fopen(argv[1], "r");
    if (csv == NULL || fgets(line, sizeof line, csv) == NULL) return 2; /* the header */
    LineFollower_init(&m);
    while (fgets(line, sizeof line, csv) != NULL) {
        if (sscanf(line, "%d,%d,%d,%d", &sensors[0], &sensors[1], &sensors[2], &sensors[3]) != 4) continue;
        LineFollower_run(&m);
        if (++tick == pause_after) sleep((unsigned)pause_s);
    }
    fclose(csv);
    if (out_fd != 1) close(out_fd);
    return 0;
}
