package org.habla.sim.world;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

class TeacherTest {

    /** A voice that writes down what the teacher gives. */
    static class Transcript implements TeacherVoice {
        final List<String> said = new ArrayList<>();

        @Override
        public synchronized double giveCommand(String label) {
            said.add(label);
            return 0;
        }

        @Override
        public synchronized void giveReward(double value) {
            said.add(value > 0 ? "+" : "-");
        }
    }

    private final Transcript voice = new Transcript();
    private final Target target = new Target(4, 1, 0.15, "pink");
    private final Teacher teacher = new Teacher(TeacherSettings.DEFAULTS, voice);

    @Test
    void theCommandPointsTheRobotTowardsTheTarget() {
        assertThat(teacher.commandTowards(new Pose2(1, 1, 0), target)).isEqualTo("forward");
        assertThat(teacher.commandTowards(new Pose2(1, 1, -Math.PI / 2), target)).isEqualTo("left");
        assertThat(teacher.commandTowards(new Pose2(1, 1, Math.PI / 2), target)).isEqualTo("right");
        assertThat(teacher.commandTowards(new Pose2(1, 1, 0.3), target)).isEqualTo("forward");
        assertThat(teacher.commandTowards(new Pose2(1, 1, 0.4), target)).isEqualTo("right");
    }

    @Test
    void aRobotThatTurnsAsToldIsRewardedAndOneThatDoesNotIsPunished() {
        Pose2 facingAway = new Pose2(1, 1, Math.PI / 2);
        teacher.step(2.99, facingAway, target);
        assertThat(voice.said).isEmpty();
        teacher.step(3.0, facingAway, target);
        assertThat(voice.said).containsExactly("right");
        teacher.step(4.0, facingAway, target);
        teacher.step(4.5, new Pose2(1, 1, Math.PI / 2 - 0.3), target);
        assertThat(voice.said).containsExactly("right", "+");
        assertThat(teacher.lastReward()).isEqualTo(1.0);
        // Next command at 6.0; the robot stays put, so it is punished once the teacher's patience is over, at 9.0.
        teacher.step(6.0, new Pose2(1, 1, Math.PI / 2 - 0.3), target);
        teacher.step(7.5, new Pose2(1, 1, Math.PI / 2 - 0.3), target);
        teacher.step(8.99, new Pose2(1, 1, Math.PI / 2 - 0.3), target);
        assertThat(voice.said).as("still waiting for an answer").containsExactly("right", "+", "right");
        teacher.step(9.0, new Pose2(1, 1, Math.PI / 2 - 0.3), target);
        assertThat(voice.said).containsExactly("right", "+", "right", "-");
        assertThat(teacher.lastCommand()).isEqualTo("right");
        assertThat(teacher.lastReward()).isEqualTo(-1.0);
    }

    @Test
    void theEpisodeTallyCountsCommandsPleasureAndPainAndStartsAgainWithEachEpisode() {
        Pose2 facingAway = new Pose2(1, 1, Math.PI / 2);
        teacher.step(3.0, facingAway, target);
        teacher.step(4.5, new Pose2(1, 1, Math.PI / 2 - 0.3), target);
        teacher.step(6.0, new Pose2(1, 1, Math.PI / 2 - 0.3), target);
        teacher.step(7.5, new Pose2(1, 1, Math.PI / 2 - 0.3), target);
        teacher.step(9.0, new Pose2(1, 1, Math.PI / 2 - 0.3), target);
        teacher.rewardNow(0.5);
        assertThat(teacher.episodeTally()).isEqualTo(new Teacher.Tally(2, 2, 1));
        var json = new GroundTruth(7.5, facingAway, target, 1, 0, false, true, teacher.lastCommand(),
                teacher.lastReward(), teacher.episodeCommands(), teacher.episodePlus(), teacher.episodeMinus(), 0).toJson();
        assertThat(json.path("teacher").path("commands").asInt()).isEqualTo(2);
        assertThat(json.path("teacher").path("plus").asInt()).isEqualTo(2);
        assertThat(json.path("teacher").path("minus").asInt()).isEqualTo(1);
        teacher.newEpisode();
        assertThat(teacher.episodeTally()).isEqualTo(new Teacher.Tally(0, 0, 0));
        assertThat(teacher.commandCount()).as("the totals keep counting").isEqualTo(2);
    }

    @Test
    void aSpokenCommandIsJudgedFromTheEndOfThePhrase() {
        Transcript slow = new Transcript() {
            @Override
            public synchronized double giveCommand(String label) {
                super.giveCommand(label);
                return 1.0;
            }
        };
        Teacher speaking = new Teacher(TeacherSettings.DEFAULTS, slow);
        Pose2 facingAway = new Pose2(1, 1, Math.PI / 2);
        speaking.step(3.0, facingAway, target);
        speaking.step(4.5, facingAway, target);
        assertThat(slow.said).as("not judged 1.5 s after the phrase began").containsExactly("right");
        speaking.step(5.4, new Pose2(1, 1, Math.PI / 2 - 0.3), target);
        speaking.step(5.5, new Pose2(1, 1, Math.PI / 2 - 0.3), target);
        assertThat(slow.said).as("judged 1.5 s after it ended").containsExactly("right", "+");
    }

    @Test
    void aRobotThatHasNotMovedYetIsJudgedOnItsFirstMoveWithinTheTeachersPatience() {
        Pose2 facingAway = new Pose2(1, 1, Math.PI / 2);
        teacher.step(3.0, facingAway, target);
        teacher.step(4.5, facingAway, target);
        teacher.step(5.0, facingAway, target);
        assertThat(voice.said).as("a robot that heard the command late has not answered yet").containsExactly("right");
        teacher.step(5.9, new Pose2(1, 1, Math.PI / 2 - 0.1), target);
        assertThat(voice.said).as("its late but right turn is rewarded").containsExactly("right", "+");
        teacher.step(6.3, new Pose2(1, 1, Math.PI / 2 - 0.1), target);
        assertThat(voice.said).as("the next command waits half a second after the judgement").containsExactly("right", "+");
        teacher.step(6.4, new Pose2(1, 1, Math.PI / 2 - 0.1), target);
        assertThat(voice.said).containsExactly("right", "+", "right");
        // A wrong move, late, is punished as soon as it shows: the patience waits for an answer, not for the right one.
        teacher.step(8.5, new Pose2(1, 1, Math.PI / 2 - 0.1), target);
        assertThat(voice.said).containsExactly("right", "+", "right");
        teacher.step(8.7, new Pose2(1, 1, Math.PI / 2 + 0.1), target);
        assertThat(voice.said).containsExactly("right", "+", "right", "-");
    }

    @Test
    void aRobotThatAlreadyMovedIsJudgedWithoutWaiting() {
        Pose2 facingAway = new Pose2(1, 1, Math.PI / 2);
        teacher.step(3.0, facingAway, target);
        teacher.step(4.5, new Pose2(1, 1.1, Math.PI / 2), target);
        assertThat(voice.said).as("it went forward when told to turn").containsExactly("right", "-");
        assertThat(teacher.moved(facingAway, facingAway.moved(0, 0, 0.04))).isFalse();
        assertThat(teacher.moved(facingAway, facingAway.moved(0, 0, -0.06))).isTrue();
        assertThat(teacher.moved(facingAway, facingAway.moved(-0.03, 0, 0))).isTrue();
    }

    @Test
    void aNewEpisodeDropsTheJudgementOfTheCommandBeforeIt() {
        Pose2 facingAway = new Pose2(1, 1, Math.PI / 2);
        teacher.step(3.0, facingAway, target);
        teacher.newEpisode();
        teacher.step(4.5, new Pose2(2, 1, 0), target);
        teacher.step(5.9, new Pose2(2, 1, 0), target);
        assertThat(voice.said).containsExactly("right");
        teacher.step(6.0, new Pose2(2, 1, 0), target);
        assertThat(voice.said).containsExactly("right", "forward");
    }

    @Test
    void forwardAndBackAreJudgedByDisplacementAlongTheHeading() {
        Pose2 from = new Pose2(1, 1, Math.PI / 4);
        assertThat(teacher.obeyed("forward", from, from.moved(0.1, 0, 0))).isTrue();
        assertThat(teacher.obeyed("forward", from, from.moved(-0.1, 0, 0))).isFalse();
        assertThat(teacher.obeyed("forward", from, from.moved(0, 0.1, 0))).isFalse();
        assertThat(teacher.obeyed("back", from, from.moved(-0.1, 0, 0))).isTrue();
        assertThat(teacher.obeyed("left", from, from.moved(0, 0, 0.2))).isTrue();
        assertThat(teacher.obeyed("left", from, from.moved(0, 0, -0.2))).isFalse();
    }

    @Test
    void anAbsentTeacherSaysNothingUntilAskedAndCanStillBeMadeToSpeak() {
        teacher.setPresent(false);
        for (int i = 1; i <= 100; i++) {
            teacher.step(i * 0.1, new Pose2(1, 1, 0), target);
        }
        assertThat(voice.said).isEmpty();
        teacher.commandNow("back", new Pose2(1, 1, 0));
        teacher.step(11.6, new Pose2(0.8, 1, 0), target);
        teacher.rewardNow(-0.5);
        assertThat(voice.said).containsExactly("back", "+", "-");
        assertThat(teacher.commandCount()).isEqualTo(1);
        assertThat(teacher.rewardCount()).isEqualTo(2);
        assertThatThrownBy(() -> teacher.commandNow("sideways", Pose2.ORIGIN)).hasMessageContaining("sideways");
        assertThatThrownBy(() -> teacher.rewardNow(2)).hasMessageContaining("[-1, 1]");
    }
}
