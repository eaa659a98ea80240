// A Flamenco 3 job type for Spindulys (docs/farm.md): put it in the Manager's scripts/ folder.
// Each task runs the render command through Flamenco's `exec` command on a chunk of contiguous
// frames; `render` exits non-zero on any failure, which fails the task, and prints a line at least
// every two seconds (--progress plain), which the Worker streams into the task log.

const JOB_TYPE = {
  label: "Spindulys",
  settings: [
    { key: "scene", type: "string", subtype: "file_path", required: true,
      description: "The scene file, on shared storage" },
    { key: "frames", type: "string", required: true, default: "1-24",
      description: "Frames A-B of the scene's animation" },
    { key: "chunk_size", type: "int32", default: 4,
      description: "Contiguous frames per task (one scene load each)" },
    { key: "render_output", type: "string", subtype: "file_path", required: true,
      description: "Output pattern with a run of # for the frame number, e.g. /shared/shot/frame_####.png" },
    { key: "render_command", type: "string", default: "render",
      description: "The render command on the Workers" },
  ],
};

function compileJob(job) {
  const s = job.settings;
  // Flamenco's chunker gives "A-B" for a contiguous range, which is what render --frames takes;
  // a frames setting with commas (1-10,20) would give chunks render does not read.
  for (const chunk of frameChunker(s.frames, s.chunk_size)) {
    const task = author.Task(`render-${chunk}`, "misc");
    task.addCommand(author.Command("exec", {
      exe: s.render_command,
      args: [s.scene, "--frames", chunk, "-o", s.render_output, "--skip-existing", "--progress", "plain"],
    }));
    job.addTask(task);
  }
}
