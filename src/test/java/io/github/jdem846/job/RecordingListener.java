package io.github.jdem846.job;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/** A listener that records every progress update, stage by stage, in the order the stages started. */
final class RecordingListener implements JobListener {

    /** One update. */
    record Update(long done, long total) {
    }

    private final Map<String, List<Update>> stages = new LinkedHashMap<>();
    private final List<String> order = new ArrayList<>();

    @Override
    public synchronized void update(String stage, long done, long total) {
        stages.computeIfAbsent(stage, s -> new ArrayList<>()).add(new Update(done, total));
        if (order.isEmpty() || !order.get(order.size() - 1).equals(stage)) {
            order.add(stage);
        }
    }

    /** @return the stages in the order they reported, a stage named again when another came between */
    synchronized List<String> order() {
        return List.copyOf(order);
    }

    /** @return the updates of {@code stage} */
    synchronized List<Update> of(String stage) {
        return List.copyOf(stages.getOrDefault(stage, List.of()));
    }

    /**
     * Checks the contract of one stage: it reported, one total, {@code done} growing strictly within
     * [0, total], the last update {@code done == total}, and at least {@code intermediate} values strictly between
     * 0 and total.
     */
    void assertStage(String stage, int intermediate) {
        List<Update> updates = of(stage);
        assertFalse(updates.isEmpty(), stage + " reported nothing; stages: " + order());
        long total = updates.get(0).total();
        long last = -1;
        int between = 0;
        for (Update u : updates) {
            assertEquals(total, u.total(), stage + ": the total changed: " + updates);
            assertTrue(u.done() > last, stage + ": progress did not grow: " + updates);
            assertTrue(u.done() >= 0 && u.done() <= total, stage + ": outside 0.." + total + ": " + updates);
            last = u.done();
            if (u.done() > 0 && u.done() < total) {
                between++;
            }
        }
        assertEquals(total, last, stage + " did not end at its total: " + updates);
        assertTrue(between >= intermediate, stage + ": only " + between + " intermediate values, expected ≥ "
                + intermediate + ": " + updates);
    }
}
