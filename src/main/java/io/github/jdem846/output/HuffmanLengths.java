package io.github.jdem846.output;

import java.util.Arrays;

/**
 * Lengths of an optimal prefix code with a longest length, for {@link HuffmanBlocks}: Moffat and Katajainen's
 * in-place minimum-redundancy algorithm on the counts in ascending order, then, where a code comes out longer than
 * allowed, the lengths moved down and the Kraft sum brought back to one as miniz does
 * ({@code tdefl_huffman_enforce_max_code_size}). Ties between equal counts go by symbol, so the lengths depend only
 * on the counts. Not thread-safe.
 */
final class HuffmanLengths {

    private final long[] keys;
    private final int[] depths;
    private final int[] perLength;

    /** For alphabets of up to {@code symbols} symbols. */
    HuffmanLengths(int symbols) {
        keys = new long[symbols];
        depths = new int[symbols];
        perLength = new int[symbols + 1];
    }

    /**
     * Writes into {@code lengths} the code length of each symbol of {@code counts} (0 for a count of 0): a complete
     * code when two or more symbols occur, length 1 for a lone symbol.
     *
     * @param maxBits the longest code allowed; 2<sup>maxBits</sup> must be at least the number of symbols
     */
    void lengths(int[] counts, int maxBits, int[] lengths) {
        int n = counts.length;
        Arrays.fill(lengths, 0, n, 0);
        int m = 0;
        for (int s = 0; s < n; s++) {
            if (counts[s] > 0) {
                keys[m++] = (long) counts[s] << 16 | s;
            }
        }
        if (m == 0) {
            return;
        }
        if (m == 1) {
            lengths[(int) keys[0] & 0xFFFF] = 1;
            return;
        }
        Arrays.sort(keys, 0, m);
        for (int i = 0; i < m; i++) {
            depths[i] = (int) (keys[i] >>> 16);
        }
        minimumRedundancy(depths, m);
        if (depths[0] > maxBits) {
            limit(m, maxBits);
        }
        for (int i = 0; i < m; i++) {
            lengths[(int) keys[i] & 0xFFFF] = depths[i];
        }
    }

    /**
     * Moffat and Katajainen (1995): {@code a[0, n)}, counts in ascending order, becomes the code lengths, longest
     * first.
     */
    private static void minimumRedundancy(int[] a, int n) {
        a[0] += a[1];
        int root = 0;
        int leaf = 2;
        for (int next = 1; next < n - 1; next++) {
            if (leaf >= n || a[root] < a[leaf]) {
                a[next] = a[root];
                a[root++] = next;
            } else {
                a[next] = a[leaf++];
            }
            if (leaf >= n || root < next && a[root] < a[leaf]) {
                a[next] += a[root];
                a[root++] = next;
            } else {
                a[next] += a[leaf++];
            }
        }
        a[n - 2] = 0;
        for (int next = n - 3; next >= 0; next--) {
            a[next] = a[a[next]] + 1;
        }
        int available = 1;
        int used = 0;
        int depth = 0;
        int root2 = n - 2;
        int next = n - 1;
        while (available > 0) {
            while (root2 >= 0 && a[root2] == depth) {
                used++;
                root2--;
            }
            while (available > used) {
                a[next--] = depth;
                available--;
            }
            available = 2 * used;
            depth++;
            used = 0;
        }
    }

    /** Makes the lengths in {@link #depths} at most {@code maxBits}, the code still complete. */
    private void limit(int m, int maxBits) {
        Arrays.fill(perLength, 0);
        for (int i = 0; i < m; i++) {
            perLength[Math.min(depths[i], maxBits)]++;
        }
        long total = 0;
        for (int b = maxBits; b > 0; b--) {
            total += (long) perLength[b] << (maxBits - b);
        }
        while (total != 1L << maxBits) {
            perLength[maxBits]--;
            for (int b = maxBits - 1; b > 0; b--) {
                if (perLength[b] != 0) {
                    perLength[b]--;
                    perLength[b + 1] += 2;
                    break;
                }
            }
            total--;
        }
        int k = 0;
        for (int b = maxBits; b > 0; b--) {
            for (int j = 0; j < perLength[b]; j++) {
                depths[k++] = b;
            }
        }
    }
}
