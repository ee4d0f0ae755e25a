package io.github.jdem846.io.mosaic;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.TreeSet;

/**
 * How the files of a mosaic cover its grid: the cells some file covers, and which files meet another. Computed
 * once from the placements (x-slabs, each a union of row intervals), without touching any cell.
 *
 * @param coveredCells cells covered by at least one file
 * @param maxDepth     the most files covering one cell
 * @param overlapping  for each file, true when it shares cells with another
 */
record Coverage(long coveredCells, int maxDepth, boolean[] overlapping) {

    static Coverage of(List<Member> members) {
        boolean[] overlapping = new boolean[members.size()];
        for (int i = 0; i < members.size(); i++) {
            for (int j = i + 1; j < members.size(); j++) {
                if (members.get(i).overlaps(members.get(j))) {
                    overlapping[i] = true;
                    overlapping[j] = true;
                }
            }
        }
        long[] union = union(members);
        return new Coverage(union[0], (int) union[1], overlapping);
    }

    /** @return true when some cells are covered by more than one file */
    boolean anyOverlap() {
        for (boolean b : overlapping) {
            if (b) {
                return true;
            }
        }
        return false;
    }

    /** Cells covered, and the most files covering one cell. */
    private static long[] union(List<Member> members) {
        TreeSet<Integer> xs = new TreeSet<>();
        for (Member m : members) {
            xs.add(m.col());
            xs.add(m.col() + m.width());
        }
        Integer[] edges = xs.toArray(new Integer[0]);
        long area = 0;
        int depth = 0;
        List<int[]> spans = new ArrayList<>();
        for (int i = 0; i + 1 < edges.length; i++) {
            int x0 = edges[i];
            int x1 = edges[i + 1];
            spans.clear();
            for (Member m : members) {
                if (m.col() <= x0 && m.col() + m.width() >= x1) {
                    spans.add(new int[] {m.row(), m.row() + m.height()});
                }
            }
            int[][] sorted = spans.toArray(new int[0][]);
            Arrays.sort(sorted, (a, b) -> Integer.compare(a[0], b[0]));
            long rows = 0;
            int start = Integer.MIN_VALUE;
            int end = Integer.MIN_VALUE;
            for (int[] s : sorted) {
                if (s[0] > end) {
                    rows += end - (long) start;
                    start = s[0];
                    end = s[1];
                } else {
                    end = Math.max(end, s[1]);
                }
            }
            rows += end - (long) start;
            area += rows * (x1 - x0);
            depth = Math.max(depth, depth(sorted));
        }
        return new long[] {area, depth};
    }

    /** The most of the intervals (sorted by start) that hold one point. */
    private static int depth(int[][] sorted) {
        int[] ends = new int[sorted.length];
        for (int i = 0; i < sorted.length; i++) {
            ends[i] = sorted[i][1];
        }
        Arrays.sort(ends);
        int most = 0;
        int open = 0;
        int e = 0;
        for (int[] s : sorted) {
            while (e < ends.length && ends[e] <= s[0]) {
                e++;
                open--;
            }
            open++;
            most = Math.max(most, open);
        }
        return most;
    }
}
