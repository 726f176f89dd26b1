// vtkBarycentricShellMapper: the records a slice outside the mesh keeps of a boundary between it and
// its neighbour slice (marker //UV::ShellRecord), written by uvBarycentricShellSliceFS.glsl and read
// by uvBarycentricShellBlendFS.glsl. A slice inside the mesh holds scalar + 1 (>= 1); a record is
// below 1 and says how much of the segment next to the slice is inside, and the scalar at the
// boundary. Entries lie in [0.01, 0.25), exits in [0.51, 0.75): the MAX blend keeps exits over
// entries, the nearest entry and the last exit, and inside values over any record.
const float EntryRecords = 0.01, ExitRecords = 0.51, RecordSpan = 0.24;
// The inside part is quantised to RecordLevels levels; each level's width holds the scalar, within
// margins that keep rounding from carrying it into the next level.
const float RecordLevels = 2048.0, RecordMargin = 0.0005, RecordScalarShare = 0.999;

/// A record: `base` (EntryRecords, ExitRecords), the part of the segment inside (0 to 1) and the
/// normalised scalar at the boundary.
float Record(float base, float inside, float scalar)
{
  float level = clamp(floor(inside * RecordLevels), 0.0, RecordLevels - 1.0);
  return base + RecordSpan * (level + RecordMargin + RecordScalarShare * clamp(scalar, 0.0, 1.0)) / RecordLevels;
}

/// Whether `value` is a record from `base`.
bool IsRecord(float value, float base)
{
  return value > base - 0.005 && value < base + RecordSpan + 0.005;
}

/// A record's inside part (the middle of its level) and scalar.
vec2 ReadRecord(float value, float base)
{
  float x = max(value - base, 0.0) / RecordSpan * RecordLevels;
  float level = min(floor(x), RecordLevels - 1.0);
  return vec2((level + 0.5) / RecordLevels, clamp((x - level - RecordMargin) / RecordScalarShare, 0.0, 1.0));
}
